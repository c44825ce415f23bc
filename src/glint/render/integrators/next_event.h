// Next-event estimation for the physically based integrators: at a surface point, one light
// picked in proportion to its power (or, with image.next_event: all, every light), a point drawn
// on it (or a direction towards the sky), and a shadow ray. A light of intensity I_L gives
// irradiance pi I_L facing it (light.h), an emitting object's or the sky's pi I_L being Le over
// the density of the direction drawn, so the estimate of the light reflected towards wo is
//   f(wo, L) |N.L| pi I_L shadow / pick,
// pick being 1 when every light is sampled.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>

#include "glint/render/explain/ray_tree.h"
#include "glint/render/integrators/shadow_feelers.h"
#include "glint/render/ray_stats.h"
#include "glint/render/world.h"
#include "glint/sampling/discrete_distribution.h"
#include "glint/sampling/sampler.h"
#include "glint/shading/bsdf.h"

namespace glint {

struct SurfaceContext;

// The lights, world.lights() then world.object_lights(), then the sky unless it is black, by
// power: built once a render.
struct NextEventLights {
    explicit NextEventLights(const World& world);
    std::shared_ptr<const DiscreteDistribution> pick;  // null when nothing lights the scene
    bool sky = false;                                  // the last entry is the sky
    bool all = false;                                  // every light at each point
};

// Per thread (its shadow feelers keep caches).
class NextEvent {
public:
    NextEvent(const World& world, const NextEventLights& lights)
        : world_(world), lights_(lights), feelers_(world, /*opaque=*/true) {}

    // The light one light (or every light) sends to c through bsdf, drawing its numbers from
    // the stream. With weigh, an emitting object's sample is weighed by the power heuristic
    // against the BSDF's density for its direction (the path tracer, whose scattered rays find
    // emitters too). The sky's sample is weighed too. With a record, the numbers of each light
    // sampled are appended there.
    Color estimate(const SurfaceContext& c, const Bsdf& bsdf, float time, SampleStream& stream,
                   RayStats& stats, bool weigh, PathVertexRecord* record);

    // The density per steradian, the pick included, with which estimate() from `from` draws the
    // point q (normal n) of object_lights()[index]: what a scattered ray that found it weighs.
    float object_light_pdf(std::size_t index, Point3 from, Point3 q, Normal3 n) const;
    // The same for the sky's direction w: what a scattered ray that left the scene weighs.
    float sky_pdf(Vector3 w) const;
    bool any() const { return lights_.pick != nullptr; }

private:
    // The probability light `index` is sampled with at a point.
    float pick(std::size_t index) const;
    Color estimate_light(std::size_t index, float pick, Point2 u, const SurfaceContext& c,
                         const Bsdf& bsdf, float time, RayStats& stats, bool weigh,
                         PathVertexRecord* record);
    std::string light_name(std::size_t index) const;

    const World& world_;
    const NextEventLights& lights_;
    ShadowFeelers feelers_;
};

// The power heuristic with exponent 2 (Veach and Guibas 1995): the weight of a sample drawn with
// density a that another strategy could have drawn with density b.
inline float power_heuristic(float a, float b) {
    const float a2 = a * a, b2 = b * b;
    return a2 + b2 > 0 ? a2 / (a2 + b2) : 0;
}

}  // namespace glint
