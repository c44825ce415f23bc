// Drawing points on a shape's surface with their density by area: what makes an object that
// emits light a light that shadow rays can aim at. Spheres, disks, triangles, convex polygons,
// boxes, cylinders, meshes and transformed ones of them can be drawn on; other shapes cannot.
#pragma once

#include <memory>
#include <optional>
#include <variant>
#include <vector>

#include "glint/math/transform.h"
#include "glint/math/vector.h"
#include "glint/sampling/discrete_distribution.h"
#include "glint/sampling/warp.h"

namespace glint {

struct Shape;

struct SurfaceSample {
    Point3 p;
    Normal3 normal;  // unit, the shape's geometric normal there
    float pdf = 0;   // density per unit area at p
};

class SurfaceSampler {
public:
    // Nothing when the shape cannot be drawn on (planes and other unbounded shapes, quadrics,
    // implicit surfaces, fractals, CSG, cones, tori, concave polygons).
    static std::optional<SurfaceSampler> of(const Shape& shape);

    // A point drawn from u in [0,1)^2. Uniform by area, except that a transform that is not a
    // similarity stretches some parts more than others: the pdf says by how much.
    SurfaceSample sample(Point2 u) const;
    // A point drawn for lighting the point `from`: on a lone sphere, uniformly over the cone of
    // directions it fills as seen from there, which draws no point on its hidden side and keeps
    // the points near it from flickering; on any other shape sample(u). The pdf is per unit area
    // either way.
    SurfaceSample sample_seen_from(Point3 from, Point2 u) const;
    // The density per unit area with which sample_seen_from(from, u) draws the point q of the
    // surface, whose unit normal there is n: for multiple importance sampling, which weighs a
    // point drawn another way by it.
    float pdf_seen_from(Point3 from, Point3 q, Normal3 n) const;
    // The surface's area in world space: exact, but for a transform that stretches some parts
    // more than others, where it is the mean over 256 points spread evenly on the object.
    float area() const;

    // The pieces a shape is drawn from: flat or round patches, chosen by area.
    struct Sphere {
        Point3 center;
        float radius;
    };
    struct Annulus {  // a disk, or a ring when inner > 0
        Point3 center;
        Vector3 s, t;  // unit, in the plane
        Normal3 normal;
        float inner, outer;
    };
    struct Parallelogram {  // corner + a e1 + b e2, a and b in [0, 1]
        Point3 corner;
        Vector3 e1, e2;
        Normal3 normal;
    };
    struct Triangle {
        Point3 v0, v1, v2;
        Normal3 normal;
    };
    struct Tube {  // a cylinder's side
        Point3 base;
        Vector3 axis, s, t;  // axis: base to top (full length); s, t unit, across it
        float radius;
    };
    using Piece = std::variant<Sphere, Annulus, Parallelogram, Triangle, Tube>;

private:
    SurfaceSampler() = default;

    std::vector<Piece> pieces_;
    std::shared_ptr<const DiscreteDistribution> by_area_;  // over pieces_, when more than one
    float area_ = 0;                                       // of pieces_
    // For a transformed shape: world_from_object, and pieces_ in object space.
    std::optional<Transform> transform_;
};

}  // namespace glint
