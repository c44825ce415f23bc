// Property checks every shape must pass on random rays, shared by the shapes' tests: hits lie on
// the surface, normals are unit length and agree with the surface, and a ray leaving the surface
// does not hit it again right away.
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "glint/geometry/surface_point.h"
#include "glint/math/interval.h"
#include "glint/math/ray.h"

namespace glint::testing {

// Random rays from a sphere of radius 4 * size around `target`, aimed at points within `size`
// of it; deterministic for a given seed.
class RandomRays {
public:
    RandomRays(Point3 target, float size, unsigned seed = 12345)
        : target_(target), size_(size), rng_(seed) {}

    Vector3 direction() {
        for (;;) {
            const Vector3 v{unit_(rng_), unit_(rng_), unit_(rng_)};
            if (const float l2 = length_squared(v); l2 > 1e-4f && l2 <= 1) return v / std::sqrt(l2);
        }
    }
    Ray next() {
        const Point3 origin = target_ + direction() * (4 * size_);
        const Point3 aim = target_ + Vector3{unit_(rng_), unit_(rng_), unit_(rng_)} * size_;
        return {origin, normalize(aim - origin)};
    }

private:
    Point3 target_;
    float size_;
    std::mt19937 rng_;
    std::uniform_real_distribution<float> unit_{-1, 1};
};

struct PropertyOptions {
    int rays = 2000;
    int min_hits = 200;
    float surface_tolerance = 1e-5f;  // |distance_to_surface(p)| of hit points
    // Whether any ray leaving the surface is free of the shape (convex shapes). Otherwise only
    // hits closer than min_rehit_distance count as failures (self-intersection).
    bool convex = false;
    float leave_offset = 1e-4f;  // how far the leaving ray starts off the surface
    float min_rehit_distance = 1e-3f;
    // Whether distance_to_surface is smooth and grows outwards, so that its gradient (by central
    // differences of step gradient_step) must point along the normal: the cosine between them at
    // least gradient_min_cos.
    bool normal_matches_gradient = false;
    float gradient_step = 1e-3f;
    float gradient_min_cos = 0.99f;
    // The fraction of hits whose normal may disagree with the gradient: 0 for smooth surfaces;
    // for piecewise ones, the hits within gradient_step of an edge, where the function has a
    // kink inside the difference stencil.
    float gradient_mismatch_fraction = 0;
};

// distance_to_surface(Point3) is zero on the surface (a signed distance or any implicit
// function with unit gradient near the surface). gradient(Point3), when given, is compared with
// the normal's direction.
template <typename S, typename Distance>
void expect_shape_properties(const S& shape, Distance distance_to_surface, RandomRays rays,
                             const PropertyOptions& options = {}) {
    int hits = 0, gradient_mismatches = 0;
    for (int i = 0; i < options.rays; ++i) {
        const Ray ray = rays.next();
        const auto hit = shape.intersect(ray, {});
        if (!hit) continue;
        ++hits;
        const SurfacePoint sp = shape.surface_at(ray, *hit);
        ASSERT_NEAR(distance_to_surface(sp.p), 0, options.surface_tolerance) << "ray " << i;
        ASSERT_NEAR(distance(sp.p, ray.at(hit->t)), 0, 100 * options.surface_tolerance)
            << "ray " << i;
        ASSERT_NEAR(length(to_vector(sp.normal)), 1, 1e-5f) << "ray " << i;
        ASSERT_NEAR(length(to_vector(sp.shading_normal)), 1, 1e-5f) << "ray " << i;
        ASSERT_GT(dot(sp.normal, sp.shading_normal), 0) << "ray " << i;
        if (options.normal_matches_gradient) {
            const float h = options.gradient_step;
            const auto f = [&](Vector3 d) { return distance_to_surface(sp.p + d); };
            const Vector3 gradient{f({h, 0, 0}) - f({-h, 0, 0}), f({0, h, 0}) - f({0, -h, 0}),
                                   f({0, 0, h}) - f({0, 0, -h})};
            const float cos = dot(normalize(gradient), sp.normal);
            if (options.gradient_mismatch_fraction == 0) {
                ASSERT_GT(cos, options.gradient_min_cos) << "ray " << i;
            } else if (!(cos > options.gradient_min_cos)) {
                ++gradient_mismatches;
            }
        }

        // Leave on the side the ray came from, in a random direction of that hemisphere.
        const Normal3 n = face_forward(sp.normal, -ray.direction);
        Vector3 d = rays.direction();
        if (dot(n, d) < 0) d = -d;
        const Ray leaving{sp.p + to_vector(n) * options.leave_offset, d};
        const auto again = shape.intersect(leaving, {});
        if (options.convex) {
            ASSERT_FALSE(again) << "ray " << i
                                << " leaving a convex shape hit it at t = " << again->t;
        } else if (again) {
            ASSERT_GT(again->t, options.min_rehit_distance) << "ray " << i << " re-hit";
        }
    }
    EXPECT_GE(hits, options.min_hits);
    EXPECT_LE(gradient_mismatches, options.gradient_mismatch_fraction * float(hits))
        << "normals disagreeing with the gradient";
}

}  // namespace glint::testing
