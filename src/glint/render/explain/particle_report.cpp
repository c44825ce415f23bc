// One sample pass's particles traced pixel by pixel as render_tile traces them, each splat
// onto the explained pixel kept with its filter weight there.
#include "glint/render/explain/particle_report.h"

#include <algorithm>
#include <optional>

#include "glint/render/explain/ray_tree_recorder.h"
#include "glint/render/eye_sample.h"
#include "glint/render/film/splat_film.h"
#include "glint/render/integrators/light_tracer.h"
#include "glint/sampling/sampler.h"

namespace glint {

namespace {

constexpr std::size_t kLargest = 5;

// The name of Emitters' emitter `index`: the lights, the emitting objects, then the sky.
std::string emitter_name(const World& world, std::size_t index) {
    const std::size_t lights = world.lights().size(), objects = world.object_lights().size();
    if (index < lights) return light_name(world, index, /*object_light=*/false);
    if (index < lights + objects) return light_name(world, index - lights, /*object_light=*/true);
    return "the sky";
}

}  // namespace

ParticleReport particle_report(const World& world, const PixelSample& which) {
    const RenderSettings& settings = world.settings();
    const Camera& camera = world.camera();
    const Sampler sampler(sampler_of(settings), settings.samples_per_pixel, which.seed);
    std::optional<FilterSampling> filter;
    if (importance_samples_filter(settings)) filter.emplace(filter_of(settings));
    // The film only for the weights it gives the pixel; nothing is splatted on it.
    const SplatFilm weights(settings.width, settings.height, filter_of(settings));

    const LightIntegrator::Shared shared = LightIntegrator::prepare(world);
    LightIntegrator integrator(world, shared);
    SplatFilm unused(1, 1, filter_of(settings));
    ParticleReport report;
    ParticleContribution current;
    const ParticleObserver observe = [&](const ParticleSplat& s) {
        const float w = weights.weight(s.film, which.x, which.y);
        if (w == 0) return;
        ++report.landed;
        report.value += s.value * w;
        current.emitter = s.emitter;
        current.bounces = s.bounces;
        current.object = s.object;
        current.point = s.point;
        current.film = s.film;
        current.value = s.value;
        current.weight = w;
        report.largest.push_back(current);
        // Keep the largest few: sorted, brightest first.
        std::sort(report.largest.begin(), report.largest.end(),
                  [](const ParticleContribution& a, const ParticleContribution& b) {
                      return mean(a.value * a.weight) > mean(b.value * b.weight);
                  });
        if (report.largest.size() > kLargest) report.largest.pop_back();
    };
    integrator.observe_particles(&observe);
    RayStats stats;
    for (int y = 0; y < settings.height; ++y)
        for (int x = 0; x < settings.width; ++x) {
            const std::uint64_t pixel = std::uint64_t(y) * std::uint64_t(settings.width) + x;
            PixelPatterns patterns(sampler, pixel);
            SampleStream stream(patterns, std::uint32_t(which.sample));
            const EyeSample eye = eye_sample(camera, stream, x, y, filter ? &*filter : nullptr);
            // The eye ray draws its numbers first; the particle's follow them. Its pencil would
            // change no number the particles draw.
            integrator.trace_eye_ray(eye.ray, nullptr, stream, stats);
            current.from_x = x;
            current.from_y = y;
            integrator.trace_particle(stream, unused, stats);
        }
    report.traced = stats.particles;
    report.seen = stats.particles_seen;
    // The film resolves each particle as standing for the whole image: over the particles a
    // pixel, one unless adaptive sampling stopped some pixels or nothing emits.
    if (report.traced > 0) {
        const float scale =
            float(double(settings.width) * double(settings.height) / double(report.traced));
        report.value = report.value * scale;
        for (ParticleContribution& c : report.largest) c.weight *= scale;
    }
    for (ParticleContribution& c : report.largest) c.light = emitter_name(world, c.emitter);
    return report;
}

}  // namespace glint
