// One sample traced as render_tile traces it, with a recorder attached to the integrator.
#include "glint/render/explain/explain.h"

#include <optional>
#include <stdexcept>

#include "glint/render/explain/particle_report.h"
#include "glint/render/explain/ray_tree_recorder.h"
#include "glint/render/eye_sample.h"
#include "glint/render/integrators/integrator_family.h"
#include "glint/sampling/sampler.h"

namespace glint {

RayTree explain(const World& world, const PixelSample& which) {
    const RenderSettings& settings = world.settings();
    if (settings.integrator == IntegratorKind::cone || settings.integrator == IntegratorKind::beam)
        throw std::invalid_argument(
            "explain follows rays; the " + std::string(integrator_name(settings.integrator)) +
            " integrator traces " + std::string(integrator_name(settings.integrator)) + "s");
    const Camera& camera = world.camera();
    const Sampler sampler(sampler_of(settings), settings.samples_per_pixel, which.seed);
    const std::uint64_t pixel =
        std::uint64_t(which.y) * std::uint64_t(settings.width) + std::uint64_t(which.x);
    PixelPatterns patterns(sampler, pixel);
    SampleStream stream(patterns, std::uint32_t(which.sample));
    std::optional<FilterSampling> filter;
    if (importance_samples_filter(settings)) filter.emplace(filter_of(settings));
    // The eye ray carries its pencil whether or not the render's does, to tell how wide each
    // ray's is: a footprint changes only the lookups of textures filtered over one, which make
    // the render carry it too.
    const EyeSample eye = eye_sample(camera, stream, which.x, which.y, filter ? &*filter : nullptr,
                                     eye_pencil_scale(settings.samples_per_pixel));

    RayTree tree;
    tree.x = which.x;
    tree.y = which.y;
    tree.sample = which.sample;
    tree.seed = which.seed;
    tree.integrator = integrator_name(settings.integrator);
    tree.film = eye.film;
    if (filter) tree.filter_weight = eye.weight;
    tree.draws.push_back({"pixel", kPixelDimension, eye.offset});
    if (camera.has_lens()) tree.draws.push_back({"lens", kLensDimension, eye.lens});
    if (camera.has_shutter())
        tree.draws.push_back({"time", kTimeDimension, {eye.time_u, 0}, false});
    RayTreeRecorder recorder(world, tree);
    tree.sample_value = with_integrator(settings.integrator, [&]<class Integrator>() {
        typename Integrator::Shared shared = Integrator::prepare(world);
        if constexpr (requires(RayStats & r) {
                          Integrator::begin_pass(shared, world, 0, std::uint64_t(0), r);
                      }) {
            RayStats unused;
            Integrator::begin_pass(shared, world, which.sample, which.seed, unused);
        }
        Integrator integrator(world, shared);
        integrator.record_into(&recorder);
        RayStats stats;
        return integrator.trace_eye_ray(eye.ray, eye.pencil_or_null(), stream, stats);
    });
    if (settings.integrator == IntegratorKind::light)
        tree.particles = particle_report(world, which);
    return tree;
}

}  // namespace glint
