// An implicit surface: the zeros of an expression f(x, y, z) inside a box. Rays find the first
// root of f along them by interval subdivision with safeguarded Newton refinement; the notes'
// "subtract the ray equation from the surface equation and find the positive real roots".
#pragma once

#include <memory>
#include <optional>
#include <string>

#include "glint/geometry/expression.h"
#include "glint/geometry/surface_point.h"
#include "glint/math/bounds.h"
#include "glint/math/interval.h"
#include "glint/math/ray.h"

namespace glint {

struct ImplicitSurface {
    // The function; never null. Its inside is f < 0, its outside f > 0: normals point along
    // grad f.
    std::shared_ptr<const Expression> f;
    // The surface is { p in region : f(p) = 0 }. Finite and not empty.
    Bounds3 region{{-1, -1, -1}, {1, 1, 1}};
    // Width in t (scene units, as ray directions are unit) below which a piece of the ray is
    // not split further: the resolution of the search. > 0. See docs/implicit-surfaces.md.
    float tolerance = 1e-4f;
    // Pieces of the ray a search may examine (each costs two interval evaluations of f); when
    // they run out the ray misses. >= 1.
    int max_segments = 4096;

    // Splits stop at this depth even above the tolerance: 2^-48 of the clipped ray.
    static constexpr int kMaxDepth = 48;

    Bounds3 bounds() const { return region; }
    std::optional<ShapeHit> intersect(const Ray& ray, Interval t_range) const;
    // normal = grad f / |grad f| at the hit (or -ray.direction where the gradient vanishes or
    // is not finite). uv: spherical about the region's centre, as for Sphere: u = longitude / 2pi
    // around +y from +x, v = latitude from the south pole (0) to the north pole (1).
    SurfacePoint surface_at(const Ray& ray, const ShapeHit& hit) const;
};

// What one search along a ray did; intersect() returns its hit. For tests, benchmarks and
// explanations.
struct ImplicitSearch {
    enum class Found {
        kNothing,     // no root: every piece of the ray was proven root-free
        kSignChange,  // a sign change of f, refined to a root by safeguarded Newton or bisection
        kTangential,  // a tolerance-wide piece whose enclosure holds 0, without a sign change
        kExhausted,   // max_segments ran out first: reported as a miss
    };
    std::optional<ShapeHit> hit;
    Found found = Found::kNothing;
    int segments = 0;  // pieces examined
};

ImplicitSearch find_first_root(const ImplicitSurface& surface, const Ray& ray, Interval t_range);

// A point of the region's boundary where f < 0, if the search finds one: there the solid f < 0
// reaches the box, which cuts it open, so the surface inside the box is not closed (not a
// solid for CSG). Each face is searched in squares, halved down to 1/64 of its sides (at most
// 6 x 5461 squares): a square where interval arithmetic proves f >= 0 (or f undefined) is
// dropped, the others are sampled at their centre. Nothing when no sample is negative: a cut
// narrower than the finest squares, or where f is negative only off the samples, goes unseen.
std::optional<Point3> point_cut_open(const ImplicitSurface& surface);

// What is wrong with the parameters, for the loader to report; empty when they are valid.
std::string describe_problem(const ImplicitSurface& surface);

}  // namespace glint
