// One sample traced as render_tile traces it, with a recorder attached to the integrator.
#include "glint/render/explain/explain.h"

#include <optional>
#include <string>

#include "glint/render/explain/particle_report.h"
#include "glint/render/explain/ray_tree_recorder.h"
#include "glint/render/eye_sample.h"
#include "glint/render/integrators/integrator_family.h"
#include "glint/sampling/sampler.h"
#include "glint/scene/setting_overrides.h"

namespace glint {

void check_explainable(const RenderSettings& s, const PixelSample& which) {
    if (!traces_rays(s.integrator)) {
        const std::string name(integrator_name(s.integrator));
        throw SettingsError(
            "integrator",
            "explain follows rays, and the " + name + " integrator traces " + name + "s",
            {"explain the pixel with the whitted integrator to see the rays its " + name +
             " stands for"});
    }
    if (which.x < 0 || which.y < 0 || which.x >= s.width || which.y >= s.height)
        throw SettingsError("pixel", "pixel (" + std::to_string(which.x) + ", " +
                                         std::to_string(which.y) + ") is outside the image of " +
                                         std::to_string(s.width) + "x" + std::to_string(s.height) +
                                         " pixels (0,0 to " + std::to_string(s.width - 1) + "," +
                                         std::to_string(s.height - 1) + ")");
    if (which.sample < 0 || which.sample >= s.samples_per_pixel)
        throw SettingsError("sample", "sample " + std::to_string(which.sample) + " of a pixel of " +
                                          std::to_string(s.samples_per_pixel) +
                                          " samples: samples are numbered from 0");
}

RayTree explain(const World& world, const PixelSample& which) {
    const RenderSettings& settings = world.settings();
    check_explainable(settings, which);
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
    if (!camera.sees(eye.film))
        throw SettingsError("pixel", "pixel (" + std::to_string(which.x) + ", " +
                                         std::to_string(which.y) + ") sample " +
                                         std::to_string(which.sample) +
                                         " lies outside the fisheye's circle: the camera sees "
                                         "nothing there, and the sample is black");

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
