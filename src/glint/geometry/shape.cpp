#include "glint/geometry/shape.h"

#include <algorithm>

namespace glint {

namespace {
struct NameOf {
    std::string_view operator()(const Sphere&) const { return "sphere"; }
    std::string_view operator()(const Plane&) const { return "plane"; }
    std::string_view operator()(const Triangle&) const { return "triangle"; }
    std::string_view operator()(const Box&) const { return "box"; }
    std::string_view operator()(const Transformed&) const { return "transformed"; }
    std::string_view operator()(const Csg&) const { return "csg"; }
};

struct IsSolid {
    bool operator()(const Sphere&) const { return true; }
    bool operator()(const Plane&) const { return true; }  // a half-space
    bool operator()(const Triangle&) const { return false; }
    bool operator()(const Box&) const { return true; }
    bool operator()(const Transformed& t) const { return is_solid(*t.shape); }
    bool operator()(const Csg&) const { return true; }
};

struct CsgDepth {
    int operator()(const Transformed& t) const { return csg_depth(*t.shape); }
    int operator()(const Csg& c) const { return 1 + std::max(csg_depth(*c.a), csg_depth(*c.b)); }
    int operator()(const auto&) const { return 0; }
};
}  // namespace

std::string_view shape_name(const Shape& shape) { return std::visit(NameOf{}, shape); }

bool is_solid(const Shape& shape) { return std::visit(IsSolid{}, shape); }

int csg_depth(const Shape& shape) { return std::visit(CsgDepth{}, shape); }

}  // namespace glint
