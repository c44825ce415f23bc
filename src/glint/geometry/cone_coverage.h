// How much of a cone of rays a shape covers (Amanatides 1984): the fraction of the cone's
// cross-section that the shape's outline, seen from the apex, fills. Spheres, planes and polygons
// (triangles are polygons of three corners) have a test; other shapes have none.
#pragma once

#include <optional>
#include <span>

#include "glint/geometry/disk.h"
#include "glint/geometry/plane.h"
#include "glint/geometry/sphere.h"
#include "glint/math/vector.h"

namespace glint {

// A cone of rays from `apex` around the unit `axis`, spread = the tangent of its half-angle (the
// radius of its cross-section at distance 1).
struct RayCone {
    Point3 apex;
    Vector3 axis;
    float spread = 0;
    float time = 0;
};

// What a shape covers of a cone: the fraction of the cross-section (in (0, 1]), how far along
// the axis it lies (to blend shapes front to back), and a unit direction from the apex inside
// the covered part, nearest the axis (the ray that finds the point to shade).
struct ConeCoverage {
    float fraction;
    float depth;
    Vector3 toward;
};

std::optional<ConeCoverage> cone_coverage(const RayCone& cone, const Sphere& sphere);
std::optional<ConeCoverage> cone_coverage(const RayCone& cone, const Plane& plane);
// A flat polygon (convex or not, corners in order; a triangle's three corners).
std::optional<ConeCoverage> cone_coverage(const RayCone& cone, std::span<const Point3> corners);
// A disk (or ring) as the polygon of kDiskSides sides inscribed in it (less the inner one's).
std::optional<ConeCoverage> cone_coverage(const RayCone& cone, const Disk& disk);
inline constexpr int kDiskSides = 64;

// Whether a shape has a coverage test above: a sphere, plane, polygon, triangle or disk, placed
// as it is (not transformed). The cone tracer sees the others by its axis ray alone.
struct Shape;
bool has_cone_test(const Shape& shape);

// The area of the disk of radius r about the origin that the polygon covers, exactly (the sum
// over its edges of the signed areas the disk shares with the triangles origin, a, b).
float disk_polygon_overlap(std::span<const Point2> polygon, float r);
// The area two disks of radii a and b, d apart, share.
float disk_disk_overlap(float a, float b, float d);

}  // namespace glint
