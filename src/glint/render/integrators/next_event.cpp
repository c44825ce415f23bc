// One light, one point on it, one shadow ray; the light's weight by power worked out once.
#include "glint/render/integrators/next_event.h"

#include <cmath>
#include <vector>

#include "glint/math/constants.h"
#include "glint/render/integrators/surface_context.h"
#include "glint/shading/emission.h"
#include "glint/shading/object_light.h"

namespace glint {

NextEventLights::NextEventLights(const World& world) {
    std::vector<float> power;
    const float radius = world.scene_radius();
    for (const Light& light : world.lights()) power.push_back(mean(light_power(light, radius)));
    for (const ObjectLight& light : world.object_lights())
        power.push_back(mean(object_light_power(light)));
    if (!world.sky().is_black()) {
        power.push_back(mean(sky_power(world.sky(), {world.scene_center(), radius})));
        sky = true;
    }
    float total = 0;
    for (float& p : power) {
        if (!std::isfinite(p) || p < 0) p = 0;
        total += p;
    }
    if (total > 0) pick = std::make_shared<const DiscreteDistribution>(power);
    all = world.settings().next_event == NextEventStrategy::all;
}

float NextEvent::pick(std::size_t index) const {
    const float p = lights_.pick->probability(index);
    return lights_.all && p > 0 ? 1 : p;
}

float NextEvent::object_light_pdf(std::size_t index, Point3 from, Point3 q, Normal3 n) const {
    if (!lights_.pick) return 0;
    return pick(world_.lights().size() + index) *
           glint::object_light_pdf(world_.object_lights()[index], from, q, n);
}

float NextEvent::sky_pdf(Vector3 w) const {
    if (!lights_.sky) return 0;
    return pick(lights_.pick->size() - 1) * world_.sky().pdf(w);
}

std::string NextEvent::light_name(std::size_t index) const {
    const std::size_t lights = world_.lights().size();
    if (index < lights) return "light " + std::to_string(index);
    if (index == lights + world_.object_lights().size()) return "the sky";
    return "emitting object " + std::to_string(world_.object_lights()[index - lights].primitive);
}

Color NextEvent::estimate(const SurfaceContext& c, const Bsdf& bsdf, float time,
                          SampleStream& stream, RayStats& stats, bool weigh,
                          PathVertexRecord* record) {
    if (!lights_.pick) return {};
    if (!lights_.all) {
        const float u_pick = stream.next_1d();
        const Point2 u = stream.next_2d();
        const std::size_t index = lights_.pick->sample(u_pick);
        return estimate_light(index, pick(index), u, c, bsdf, time, stats, weigh, record);
    }
    // Every light, each with numbers of its own whether it sends light or not, so that the
    // dimensions a point takes do not depend on what it sees.
    Color sum;
    for (std::size_t index = 0; index < lights_.pick->size(); ++index) {
        const Point2 u = stream.next_2d();
        if (pick(index) > 0)
            sum += estimate_light(index, 1, u, c, bsdf, time, stats, weigh, record);
    }
    return sum;
}

Color NextEvent::estimate_light(std::size_t index, float pick, Point2 u, const SurfaceContext& c,
                                const Bsdf& bsdf, float time, RayStats& stats, bool weigh,
                                PathVertexRecord* record) {
    const auto lights = world_.lights();
    LightSample ls;
    std::size_t feeler_light = ShadowFeelers::kNoLight;
    float light_pdf = 0;
    if (index < lights.size()) {
        // Point, spot, directional and area lights: no scattered ray ever hits them. An area
        // light's point is drawn over all its shape, as the particles of the light integrator
        // leave it, so that the two agree.
        ls = sample_light_by_area(lights[index], c.sp.p, u);
        feeler_light = index;
    } else if (index == lights.size() + world_.object_lights().size()) {
        // The sky: a direction by its brightness, as far as shadow rays go.
        const Vector3 w = world_.sky().sample(u, &light_pdf);
        ls = {w, kInfinity, Color{}};
        if (light_pdf > 0) ls.intensity = world_.sky().radiance(w) / (kPi * light_pdf);
    } else {
        const ObjectLightSample s =
            sample_object_light(world_.object_lights()[index - lights.size()], c.sp.p, u);
        ls = s.light;
        light_pdf = s.pdf;
        if (!(s.pdf > 0)) ls.intensity = {};
    }
    const bool sends = !is_black(ls.intensity);
    const Color f = sends ? bsdf.eval(ls.to_light) : Color{};
    const float bsdf_pdf = sends ? bsdf.pdf(ls.to_light) : 0;
    const float mis = weigh && light_pdf > 0 ? power_heuristic(pick * light_pdf, bsdf_pdf) : 1;
    const float cosine = std::abs(dot(to_vector(c.n), ls.to_light));
    Color shadow;
    Color term;
    if (!is_black(f)) {
        // Light from behind reaches only what transmits: the feeler leaves by that side.
        const Normal3 side = dot(ls.to_light, c.ng) >= 0 ? c.ng : -c.ng;
        shadow =
            feelers_.transmittance(feeler_light, c.sp, side, ls.to_light, ls.distance, time, stats);
        if (!is_black(shadow)) term = f * ls.intensity * shadow * (kPi * cosine * mis / pick);
    }
    if (record) {
        NextEventRecord& r = record->next_events.emplace_back();
        r.light = light_name(index);
        r.pick = pick;
        r.to_light = ls.to_light;
        r.distance = ls.distance;
        r.irradiance = ls.intensity * kPi;
        r.f = f;
        r.cosine = cosine;
        r.light_pdf = light_pdf;
        r.bsdf_pdf = bsdf_pdf;
        r.mis = mis;
        r.shadow = shadow;
        r.term = term;
    }
    return term;
}

}  // namespace glint
