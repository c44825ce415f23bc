// Regions of planes, and of the image, as polygons with holes in integer coordinates: Clipper's
// (Vatti's algorithm, Debian's libpolyclipping), whose set operations are exact in integers, so
// a beam's region minus a polygon and that polygon's fragment share their edges to the bit.
// With the planes, mirrors and apparent-depth maps that carry them through a beam tree.
#pragma once

#include <clipper.hpp>

#include "glint/math/vector3d.h"

namespace glint::beam {

using ClipperLib::IntPoint;
using ClipperLib::Path;
using ClipperLib::Paths;

// The plane dot(n, x) = d; at() is positive on the side n points to.
struct PlaneD {
    Vector3d n;
    double d = 0;
    double at(Vector3d p) const { return dot(n, p) - d; }
    PlaneD flipped() const { return {n * -1.0, -d}; }
};

// x -> m x + t: the reflections in mirrors and the paraxial refractions of a beam tree, chained.
struct Affine {
    double m[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    Vector3d t;

    Vector3d apply(Vector3d p) const { return linear(p) + t; }
    Vector3d linear(Vector3d v) const;
    Vector3d linear_transposed(Vector3d v) const;
    // This map after `inner`: x -> this(inner(x)).
    Affine after(const Affine& inner) const;
    Affine inverse() const;
    // The plane of the points x whose image apply(x) lies on `plane`, sides kept.
    PlaneD pull_back(const PlaneD& plane) const;
};

// The mirror image in a plane of unit normal.
Affine mirror_in(const PlaneD& plane);
// Distances from a plane of unit normal scaled by `factor`, the plane held still: where a point
// beyond a refracting plane appears to an eye looking nearly along the normal (the paraxial
// approximation: apparent depth = depth n1 / n2).
Affine scale_across(const PlaneD& plane, double factor);

// Integer coordinates in a plane: the point (X, Y) is origin + (X u + Y v) / scale.
struct PlaneFrame {
    Vector3d origin, u, v, n;  // u, v, n orthonormal, n the plane's normal
    double scale = 1;

    Vector3d world(const IntPoint& p) const;
    IntPoint local(Vector3d p) const;  // p projected into the plane
};
PlaneFrame frame_of_plane(Vector3d origin, Vector3d unit_normal, double scale);

enum class Side { front, back, straddles, in_plane };
// Where the region's vertices lie: all at() > tolerance (front), all < -tolerance (back), all
// within it (in_plane), or some on each side.
Side side_of(const PlaneFrame& frame, const Paths& region, const PlaneD& plane, double tolerance);
// The part of a region of the frame's plane where plane.at(x) >= 0.
Paths clip_to_halfspace(const PlaneFrame& frame, const Paths& region, const PlaneD& plane);

// Set operations on regions filled by the non-zero rule. Results have outer rings of positive
// area and holes of negative area (Clipper's orientation).
Paths intersection(const Paths& a, const Paths& b);
Paths difference(const Paths& a, const Paths& b);
Paths union_of(const Paths& a);
// A polygon's outline as a region by its own fill rule (even-odd or non-zero).
Paths simplified(const Paths& outline, bool even_odd);

// Reverses every ring when the region's signed area is negative (a projection that mirrors it).
void orient_positive(Paths& region);

// The bounding box of a region; empty (left > right) for no region.
ClipperLib::IntRect bounds_of(const Paths& region);
bool overlap(const ClipperLib::IntRect& a, const ClipperLib::IntRect& b);

}  // namespace glint::beam
