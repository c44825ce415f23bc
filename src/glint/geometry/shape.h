// A Shape is one surface's geometry, as plain data: the scene describes it and the renderer
// intersects the same value. Dispatch is a switch over the alternatives, not a virtual call.
#pragma once

#include <optional>
#include <string_view>
#include <type_traits>
#include <variant>

#include "glint/geometry/box.h"
#include "glint/geometry/cone.h"
#include "glint/geometry/csg.h"
#include "glint/geometry/cylinder.h"
#include "glint/geometry/disk.h"
#include "glint/geometry/implicit_surface.h"
#include "glint/geometry/julia_set.h"
#include "glint/geometry/lathe.h"
#include "glint/geometry/mandelbulb.h"
#include "glint/geometry/moving.h"
#include "glint/geometry/plane.h"
#include "glint/geometry/polygon.h"
#include "glint/geometry/prism.h"
#include "glint/geometry/quadric.h"
#include "glint/geometry/sphere.h"
#include "glint/geometry/surface_point.h"
#include "glint/geometry/torus.h"
#include "glint/geometry/transformed.h"
#include "glint/geometry/traversal_counters.h"
#include "glint/geometry/triangle.h"
#include "glint/geometry/triangle_mesh.h"

namespace glint {

// A struct rather than an alias so that it can be forward-declared by shapes that hold other
// shapes (CSG, transforms). It is the variant: std::visit, std::get and friends apply.
struct Shape : std::variant<Sphere, Plane, Triangle, Box, Disk, Cylinder, Cone, Torus, Quadric,
                            Polygon, Prism, Lathe, TriangleMesh, ImplicitSurface, JuliaSet,
                            Mandelbulb, Transformed, Moving, Csg> {
    using variant::variant;
};

inline Bounds3 bounds(const Shape& shape) {
    return std::visit([](const auto& s) { return s.bounds(); }, shape);
}

inline std::optional<ShapeHit> intersect(const Shape& shape, const Ray& ray, Interval t_range) {
    // Planes without the variant's jump table: every ray tests the unbounded shapes beside the
    // acceleration structure, and a floor plane is the common one.
    if (const auto* plane = std::get_if<Plane>(&shape)) {
        count_primitives();
        return plane->intersect(ray, t_range);
    }
    return std::visit(
        [&](const auto& s) {
            // A mesh's block tests count its triangles instead.
            if constexpr (!std::is_same_v<std::decay_t<decltype(s)>, TriangleMesh>)
                count_primitives();
            return s.intersect(ray, t_range);
        },
        shape);
}

// Shapes whose uv is cheap take no Uv and always compute it.
inline SurfacePoint surface_at(const Shape& shape, const Ray& ray, const ShapeHit& hit,
                               Uv uv = Uv::compute) {
    return std::visit(
        [&](const auto& s) {
            if constexpr (requires { s.surface_at(ray, hit, uv); })
                return s.surface_at(ray, hit, uv);
            else
                return s.surface_at(ray, hit);
        },
        shape);
}

std::string_view shape_name(const Shape& shape);

// Whether the shape is a closed solid (or a half-space) that a ray alternately enters and
// leaves: what CSG needs of its operands.
bool is_solid(const Shape& shape);

// How many CSG levels the shape nests, through transforms and instances.
int csg_depth(const Shape& shape);

// The CSG `a operation b`, each operand painted with a material (index + 1; 0: the CSG's own).
Shape csg_of(Shape a, Shape b, CsgOperation operation, std::uint32_t material_a = 0,
             std::uint32_t material_b = 0);

}  // namespace glint
