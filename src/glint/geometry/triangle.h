// A single triangle. Its front side is the one from which the vertices run counter-clockwise.
#pragma once

#include <array>
#include <optional>

#include "glint/geometry/surface_point.h"
#include "glint/geometry/surface_sample.h"
#include "glint/math/bounds.h"
#include "glint/math/interval.h"
#include "glint/math/ray.h"

namespace glint {

struct Triangle {
    std::array<Point3, 3> vertices;
    std::array<Point2, 3> uvs{{{0, 0}, {1, 0}, {0, 1}}};

    Bounds3 bounds() const;
    // Watertight (Woop, Benthin and Wald 2013). Two-sided; hit.u and hit.v are the barycentric
    // weights of vertices 1 and 2.
    std::optional<ShapeHit> intersect(const Ray& ray, Interval t_range) const;
    // The normal is normalize((v1 - v0) x (v2 - v0)); uv interpolates the vertex uvs.
    SurfacePoint surface_at(const Ray& ray, const ShapeHit& hit) const;
    // Its area, and a point drawn uniformly by area from u in [0,1)^2: what lets it light a
    // scene.
    float area() const;
    SurfaceSample sample(Point2 u) const;
};

// The watertight test (watertight_triangle.h) on the triangle (v0, v1, v2): t, and the
// barycentric weights of v1 and v2 as u and v. Two-sided; nothing for rays in or parallel to the
// plane. Meshes share it, so a ray through an edge of a closed mesh cannot pass between the two
// triangles. Shears the ray anew on each call; see intersect_watertight to do that once a ray.
std::optional<ShapeHit> intersect_triangle(Point3 v0, Point3 v1, Point3 v2, const Ray& ray,
                                           Interval t_range);

// Twice the area; zero for collinear or coincident vertices, which no ray hits.
float double_area(const Triangle& triangle);

}  // namespace glint
