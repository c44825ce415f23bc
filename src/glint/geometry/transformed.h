// A shape placed by an affine transform. The shape is shared, not copied: placing one shape (a
// mesh, a CSG tree) many times is instancing.
#pragma once

#include <memory>
#include <optional>
#include <utility>

#include "glint/geometry/surface_point.h"
#include "glint/math/bounds.h"
#include "glint/math/interval.h"
#include "glint/math/ray.h"
#include "glint/math/transform.h"

namespace glint {

struct Shape;

struct Transformed {
    Transformed(const Transform& placement, std::shared_ptr<const Shape> placed)
        : transform(std::make_shared<const Transform>(placement)), shape(std::move(placed)) {}

    const Transform& world_from_object() const { return *transform; }

    // Held by pointer, as the shape is: two matrices inline would make every Shape 144 bytes.
    std::shared_ptr<const Transform> transform;  // never null
    std::shared_ptr<const Shape> shape;          // never null

    // The transformed box of the shape's bounds; unbounded shapes stay unbounded.
    Bounds3 bounds() const;
    // The ray is taken to object space and its direction renormalised there (shapes need unit
    // directions); t is scaled back, so hits are in world distances.
    std::optional<ShapeHit> intersect(const Ray& ray, Interval t_range) const;
    // The object's surface point mapped to world space: normals by the inverse transpose.
    SurfacePoint surface_at(const Ray& ray, const ShapeHit& hit, Uv uv = Uv::compute) const;
};

// A world-space ray in the space of an object placed by world_from_object: its direction
// renormalised there, and the factor that turns world distances along it into object ones.
struct ObjectRay {
    Ray ray;
    float scale;  // object-space t per world-space t
};
ObjectRay to_object(const Transform& world_from_object, const Ray& ray);

// The intersection and the surface point of `shape` placed by world_from_object, as Transformed
// computes them; for shapes whose placement changes from ray to ray (Moving).
std::optional<ShapeHit> intersect_placed(const Shape& shape, const Transform& world_from_object,
                                         const Ray& ray, Interval t_range);
SurfacePoint surface_at_placed(const Shape& shape, const Transform& world_from_object,
                               const Ray& ray, const ShapeHit& hit, Uv uv = Uv::compute);

}  // namespace glint
