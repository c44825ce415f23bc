// Drawing points on an emitting object's surface with their density by area: what makes an object
// that emits light a light that shadow rays can aim at. The shapes draw on themselves (their
// area() and sample(u)); this adds the transforms around them and a mesh's table of triangles.
// Spheres, disks, triangles, convex polygons, boxes, cylinders, meshes and transformed ones of
// them can be drawn on; other shapes cannot.
#pragma once

#include <memory>
#include <optional>
#include <variant>

#include "glint/geometry/box.h"
#include "glint/geometry/cylinder.h"
#include "glint/geometry/disk.h"
#include "glint/geometry/polygon.h"
#include "glint/geometry/sphere.h"
#include "glint/geometry/surface_sample.h"
#include "glint/geometry/triangle.h"
#include "glint/geometry/triangle_mesh.h"
#include "glint/math/transform.h"
#include "glint/math/vector.h"
#include "glint/sampling/discrete_distribution.h"

namespace glint {

struct Shape;

class SurfaceSampler {
public:
    // Nothing when the shape cannot be drawn on (planes and other unbounded shapes, quadrics,
    // implicit surfaces, fractals, CSG, cones, tori, concave polygons), or has no area.
    static std::optional<SurfaceSampler> of(const Shape& shape);

    // A point drawn from u in [0,1)^2. Uniform by area, except that a transform that is not a
    // similarity stretches some parts more than others: the pdf says by how much.
    SurfaceSample sample(Point2 u) const;
    // A point drawn for lighting the point `from`: on a lone sphere, Sphere::sample_seen_from;
    // on any other shape sample(u). The pdf is per unit area either way.
    SurfaceSample sample_seen_from(Point3 from, Point2 u) const;
    // The density per unit area with which sample_seen_from(from, u) draws the point q of the
    // surface, whose unit normal there is n: for multiple importance sampling, which weighs a
    // point drawn another way by it.
    float pdf_seen_from(Point3 from, Point3 q, Normal3 n) const;
    // The surface's area in world space: exact, but for a transform that stretches some parts
    // more than others, where it is the mean over 256 points spread evenly on the object.
    float area() const;

private:
    using Drawable = std::variant<Sphere, Disk, Triangle, Polygon, Box, Cylinder, TriangleMesh>;

    SurfaceSampler(Drawable shape, float area) : shape_(std::move(shape)), area_(area) {}
    SurfaceSample draw(Point2 u) const;

    Drawable shape_;  // in object space when there is a transform
    float area_;      // of shape_
    // A mesh's triangles by area.
    std::shared_ptr<const DiscreteDistribution> triangles_by_area_;
    // For a transformed shape: world_from_object.
    std::optional<Transform> transform_;
};

}  // namespace glint
