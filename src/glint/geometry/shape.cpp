// What every shape answers beside its own tests: its name, whether it is a solid, its CSG depth,
// and building the own BVH of the meshes it holds.
#include "glint/geometry/shape.h"

#include <algorithm>

namespace glint {

namespace {
struct NameOf {
    std::string_view operator()(const Sphere&) const { return "sphere"; }
    std::string_view operator()(const Plane&) const { return "plane"; }
    std::string_view operator()(const Triangle&) const { return "triangle"; }
    std::string_view operator()(const Box&) const { return "box"; }
    std::string_view operator()(const Disk&) const { return "disk"; }
    std::string_view operator()(const Cylinder&) const { return "cylinder"; }
    std::string_view operator()(const Cone&) const { return "cone"; }
    std::string_view operator()(const Torus&) const { return "torus"; }
    std::string_view operator()(const Quadric&) const { return "quadric"; }
    std::string_view operator()(const Polygon&) const { return "polygon"; }
    std::string_view operator()(const Prism&) const { return "prism"; }
    std::string_view operator()(const Lathe&) const { return "lathe"; }
    std::string_view operator()(const TriangleMesh&) const { return "mesh"; }
    std::string_view operator()(const ImplicitSurface&) const { return "implicit"; }
    std::string_view operator()(const JuliaSet&) const { return "julia"; }
    std::string_view operator()(const Mandelbulb&) const { return "mandelbulb"; }
    std::string_view operator()(const Transformed&) const { return "transformed"; }
    std::string_view operator()(const Moving&) const { return "moving"; }
    std::string_view operator()(const Csg&) const { return "csg"; }
};

struct IsSolid {
    bool operator()(const Sphere&) const { return true; }
    bool operator()(const Plane&) const { return true; }  // a half-space
    bool operator()(const Triangle&) const { return false; }
    bool operator()(const Box&) const { return true; }
    bool operator()(const Disk&) const { return false; }
    bool operator()(const Cylinder& c) const { return c.capped; }
    bool operator()(const Cone& c) const { return c.capped; }
    bool operator()(const Torus&) const { return true; }
    bool operator()(const Quadric&) const { return false; }  // clipped open by its box
    bool operator()(const Polygon&) const { return false; }
    bool operator()(const Prism& p) const { return !p.open; }
    bool operator()(const Lathe& l) const { return l.closed; }
    bool operator()(const TriangleMesh& m) const { return is_closed_surface(*m.data); }
    // Inside is f < 0; the region must enclose the surface for the solid to be closed.
    bool operator()(const ImplicitSurface& s) const { return !point_cut_open(s); }
    bool operator()(const JuliaSet&) const { return true; }
    bool operator()(const Mandelbulb&) const { return true; }
    bool operator()(const Transformed& t) const { return is_solid(*t.shape); }
    bool operator()(const Moving& m) const { return is_solid(*m.shape); }
    // A clip cuts its first operand open.
    bool operator()(const Csg& c) const { return c.operation != CsgOperation::clip; }
};

struct CsgDepth {
    int operator()(const Transformed& t) const { return csg_depth(*t.shape); }
    int operator()(const Moving& m) const { return csg_depth(*m.shape); }
    int operator()(const Csg& c) const { return 1 + std::max(csg_depth(*c.a), csg_depth(*c.b)); }
    int operator()(const auto&) const { return 0; }
};

}  // namespace

std::string_view shape_name(const Shape& shape) { return std::visit(NameOf{}, shape); }

bool is_solid(const Shape& shape) { return std::visit(IsSolid{}, shape); }

int csg_depth(const Shape& shape) { return std::visit(CsgDepth{}, shape); }

Shape csg_of(Shape a, Shape b, CsgOperation operation, std::uint32_t material_a,
             std::uint32_t material_b) {
    Csg csg;
    csg.operation = operation;
    csg.a = std::make_shared<const Shape>(std::move(a));
    csg.b = std::make_shared<const Shape>(std::move(b));
    csg.material_a = material_a;
    csg.material_b = material_b;
    return csg;
}

}  // namespace glint
