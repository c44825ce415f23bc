// Shadow maps (Williams 1978): the distance from a light to the nearest surface that casts
// shadows, stored over a grid of directions (a cube of six faces around a light at a point) or
// of parallel lines (an orthographic grid across the scene, for a directional light), rendered
// once before the image by casting a ray through each texel's centre. A surface point is lit
// when it is no farther from the light than the depth stored where it falls, plus a bias; the
// test is averaged over neighbouring texels, each weighed bilinearly (percentage-closer
// filtering, Reeves, Salesin and Cook 1987), and for a light with an extent the filter widens to
// the penumbra the blockers found imply (percentage-closer soft shadows, Fernando 2005).
#pragma once

#include <cstddef>
#include <optional>
#include <vector>

#include "glint/accel/aggregate.h"
#include "glint/math/bounds.h"
#include "glint/math/vector.h"
#include "glint/scene/scene.h"

namespace glint {

class ShadowMap {
public:
    // Six faces around `light`; light_radius > 0 for an area light (its soft shadows), seen from
    // its centre. Rendered against the primitives visible to shadow rays, on all threads, with
    // moving shapes where they are at `time`.
    static ShadowMap cube(Point3 light, float light_radius, const Aggregate& aggregate,
                          const ShadowMapSettings& settings, float time = 0);
    // An orthographic map across the sphere round `bounds`, for light travelling along the unit
    // `direction`.
    static ShadowMap parallel(Vector3 direction, const Bounds3& bounds, const Aggregate& aggregate,
                              const ShadowMapSettings& settings, float time = 0);

    // The fraction of the light that reaches p, whose geometric normal towards the light is n;
    // nothing where the map does not cover p (beyond a directional map's extent, or at the
    // light itself).
    std::optional<float> visibility(Point3 p, Normal3 n) const;

    // The depth stored for the direction d from the light (a cube), for tests: the nearest
    // surface's distance along the axis of the face d leaves by.
    float depth_towards(Vector3 d) const;
    std::size_t memory_bytes() const { return depth_.size() * sizeof(float); }

private:
    // A texel of the map: face, column, row.
    struct Texel {
        int face, i, j;
    };
    // Where the receiver q falls: the face, its continuous texel coordinates (centres at
    // integers + 1/2), and its distance from the light along the face's axis (the depths'
    // measure).
    struct Projection {
        int face;
        float x, y;
        float distance;
    };
    Projection project(Point3 q) const;
    // The texel at face coordinates (x, y), which may lie beyond the face's edge: a cube finds
    // it on the neighbouring face. Nothing beyond an orthographic map's edge.
    std::optional<Texel> texel_at(int face, float x, float y) const;
    float depth(const Texel& t) const {
        return depth_[(std::size_t(t.face) * resolution_ + std::size_t(t.j)) * resolution_ +
                      std::size_t(t.i)];
    }
    // The receiver's plane, through q with unit normal n: each texel compares its depth with
    // where its own ray meets that plane (receiver-plane depth bias), so that a filter wider
    // than a texel does not find a tilted receiver shadowing itself.
    struct Receiver {
        Point3 q;
        Vector3 n;
        float bias;  // world units
    };
    // Whether the texel's depth, plus the bias, falls short of the receiver's plane.
    bool blocks(const Texel& t, const Receiver& r) const;
    // The share of the 2 x 2 texels round (x, y), weighed bilinearly, that do not block.
    float lit_share(int face, float x, float y, const Receiver& r) const;
    // The world size of a texel at `distance` from the light.
    float texel_size(float distance) const;

    bool parallel_ = false;
    Point3 origin_;          // the light's position; the centre of an orthographic map's near face
    Vector3 axis_, s_, t_;   // an orthographic map's direction and its two sides (unit)
    float half_extent_ = 0;  // of an orthographic map
    float light_radius_ = 0;
    int resolution_ = 0;
    ShadowMapSettings settings_;
    // Face by face, row by row, the nearest surface's distance along the face's (or the map's)
    // axis; infinite where nothing is hit.
    std::vector<float> depth_;
};

}  // namespace glint
