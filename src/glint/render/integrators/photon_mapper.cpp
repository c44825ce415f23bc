// Progressive photon mapping: a pass's photons traced in blocks on every thread (their numbers a
// function of the photon's index, the pass and the seed, the blocks joined in order), and the
// eye rays' gathering.
#include "glint/render/integrators/photon_mapper.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "glint/math/constants.h"
#include "glint/render/integrators/ray_fog.h"
#include "glint/render/integrators/roulette.h"
#include "glint/render/integrators/surface_context.h"
#include "glint/render/integrators/wavelength_split.h"
#include "glint/sampling/random.h"

namespace glint {

namespace {

// Photons of a block share a task.
constexpr std::size_t kPhotonBlock = 1024;
// The photon's numbers: a stream of their own beside the pixels' (a different seed).
constexpr std::uint64_t kPhotonSeed = 0x70686f746f6e73ull;
// Photons on a surface turned more than about 25 degrees from the one gathering belong to
// another surface (a corner's other wall): left out.
constexpr float kSameSurface = 0.9f;
// An eye ray's branch at a mirror or clear glass that carries less of its sample than this goes
// on by Russian roulette, with this weight when it does.
constexpr float kSplitWeight = 0.05f;

struct PhotonNumbers {
    std::uint64_t photon, sample, seed;
    std::uint64_t dimension = 0;
    float next() { return random_float(photon, sample, dimension++, seed); }
    Point2 next_2d() {
        const float x = next();
        return {x, next()};
    }
};

// Traces photon `index` of the pass of `sample`, appending where it comes to rest.
void trace_photon(const World& world, const Emitters& emitters, std::uint64_t index, int sample,
                  std::uint64_t seed, std::vector<Photon>& out, RayStats& stats) {
    const RenderSettings& settings = world.settings();
    PhotonNumbers u{index, std::uint64_t(sample), seed ^ kPhotonSeed};
    ++stats.particles;
    const float u_pick = u.next();
    const Point2 u_position = u.next_2d(), u_direction = u.next_2d();
    const EmittedParticle e = emitters.emit(u_pick, u_position, u_direction);
    Color beta = e.power;
    if (is_black(beta)) return;
    const Camera& camera = world.camera();
    const float time = camera.has_shutter() ? camera.shutter_time(u.next()) : camera.shutter_open();
    Ray ray = world.spawn_ray(e.origin, Normal3(e.direction), e.direction, 0, time);
    MediumStack media;
    float wavelength = 0;
    Color throughput{1, 1, 1};
    bool direct = true;  // nothing met since the emitter
    for (int depth = 1; depth <= settings.max_depth; ++depth) {
        const auto hit = world.nearest_hit(ray);
        stats.count(RayKind::particle);
        if (!hit) break;
        if (const auto fade = interior_fade(media, hit->shape_hit.t)) {
            beta *= fade->transmittance;
            throughput *= fade->transmittance;
        }
        const SurfaceContext c = surface_context(world, ray, *hit);
        const Material& m = *c.material;
        const WavelengthSplit split = split_wavelength(m, wavelength, [&] { return u.next(); });
        wavelength = split.wavelength;
        const Color spectral_weight = split.weight;
        const Bsdf bsdf(bsdf_inputs(c, snell_indices(c, media, wavelength)),
                        TransportMode::importance);
        if (bsdf.has_smooth_part() && !direct) {
            out.push_back({c.sp.p, c.to_viewer, c.ng, beta});
            ++stats.photons_stored;
        }
        if (depth == settings.max_depth) break;
        const float u_lobe = u.next();
        const std::optional<BsdfSample> s = bsdf.sample(u_lobe, u.next_2d());
        if (!s) break;
        Color factor = s->weight;
        if (s->transmitted) factor *= spectral_weight;
        throughput *= factor;
        if (const float p = survival_probability(throughput, depth); p < 1) {
            if (u.next() >= p) break;
            factor = factor / p;
            throughput = throughput / p;
        }
        beta *= factor;
        direct = false;
        if (s->transmitted) {
            const float ior = ior_at(m, wavelength);
            media = c.entering ? media.entered(c.primitive, &m, ior) : media.left(c.primitive, &m);
        }
        ray = world.spawn_ray(c.sp.p, c.ng, s->wi, c.sp.error, ray.time);
        ray.wavelength = wavelength;
    }
}

}  // namespace

PhotonIntegrator::Shared PhotonIntegrator::prepare(const World& world) {
    const PhotonSettings& p = world.settings().photons;
    return {Emitters(world), NextEventLights(world),
            p.radius > 0 ? p.radius : world.scene_radius() / 50, nullptr, 0};
}

float PhotonIntegrator::radius_of_pass(float first, float alpha, int sample) {
    double r2 = double(first) * first;
    for (int i = 1; i <= sample; ++i) r2 *= (i + double(alpha)) / (i + 1);
    return float(std::sqrt(r2));
}

void PhotonIntegrator::begin_pass(Shared& shared, const World& world, int sample,
                                  std::uint64_t seed, RayStats& stats) {
    const PhotonSettings& settings = world.settings().photons;
    const auto count = std::size_t(settings.per_pass);
    const std::size_t blocks = (count + kPhotonBlock - 1) / kPhotonBlock;
    std::vector<std::vector<Photon>> found(blocks);
    std::vector<RayStats> block_stats(blocks);
    if (shared.emitters.any()) {
        tbb::parallel_for(tbb::blocked_range<std::size_t>(0, blocks, 1),
                          [&](const tbb::blocked_range<std::size_t>& range) {
                              for (std::size_t b = range.begin(); b != range.end(); ++b) {
                                  const std::size_t end = std::min(count, (b + 1) * kPhotonBlock);
                                  for (std::size_t i = b * kPhotonBlock; i < end; ++i)
                                      trace_photon(world, shared.emitters, i, sample, seed,
                                                   found[b], block_stats[b]);
                              }
                          });
    }
    std::vector<Photon> photons;
    for (std::size_t b = 0; b < blocks; ++b) {
        photons.insert(photons.end(), found[b].begin(), found[b].end());
        stats += block_stats[b];
    }
    shared.map = std::make_shared<const PhotonMap>(
        std::move(photons), radius_of_pass(shared.first_radius, settings.alpha, sample));
    shared.emitted = count;
}

Color PhotonIntegrator::gather(const SurfaceContext& c, const Bsdf& bsdf, int& found) const {
    found = 0;
    if (!shared_.map || shared_.emitted == 0) return {};
    Color sum;
    shared_.map->for_each_near(c.sp.p, [&](const Photon& p) {
        if (std::abs(dot(to_vector(p.normal), to_vector(c.sp.normal))) < kSameSurface) return;
        sum += bsdf.eval(p.from) * p.power;
        ++found;
    });
    const float r = shared_.map->radius();
    return sum / (kPi * r * r * float(shared_.emitted));
}

Color PhotonIntegrator::trace_eye_ray(const Ray& ray, const RayDifferential* pencil,
                                      SampleStream& stream, RayStats& stats) {
    stats.count(RayKind::primary);
    if (recorder_) [[unlikely]]
        return eye_ray<true>(ray, 1, world_.eye_media(), Color{1, 1, 1}, stream, pencil, stats);
    return eye_ray<false>(ray, 1, world_.eye_media(), Color{1, 1, 1}, stream, pencil, stats);
}

template <bool kRecord>
Color PhotonIntegrator::eye_ray(const Ray& ray, int depth, const MediumStack& media,
                                Color throughput, SampleStream& stream,
                                const RayDifferential* pencil, RayStats& stats) {
    const RenderSettings& settings = world_.settings();
    if constexpr (kRecord) recorder_->begin_ray(ray, depth, max_channel(throughput));
    const auto hit = world_.nearest_hit(ray);
    // Inside an object that fades, all the ray brings back fades on its way.
    const std::optional<FogEffect> fade = interior_fade(media, hit ? hit->shape_hit.t : kInfinity);
    if (!hit) {
        const Color sky = world_.sky().radiance(ray.direction);
        if constexpr (kRecord) {
            recorder_->missed(sky);
            if (fade) recorder_->fog(*fade, true);
            recorder_->end_ray(through(fade, sky));
        }
        return through(fade, sky);
    }
    if (depth == 1) ++stats.primary_hits;
    const SurfaceContext c = surface_context(world_, ray, *hit, pencil);
    if constexpr (kRecord) {
        recorder_->hit(c, *hit);
        if (fade) recorder_->fog(*fade, true);
    }
    PathVertexRecord record;
    record.le = c.emission;
    // Seen by the eye or through delta surfaces: what it emits, as the light tracer's eye.
    Color color = c.emission;
    const auto end = [&](StopReason reason) {
        color = through(fade, color);
        if constexpr (kRecord) {
            recorder_->path_vertex(c, record);
            if (reason != StopReason::none) recorder_->stop(reason);
            recorder_->end_ray(color);
        }
        return color;
    };
    if (depth > settings.max_depth) return end(StopReason::max_depth);
    const Material& m = *c.material;
    const WavelengthSplit split =
        split_wavelength(m, ray.wavelength, [&] { return stream.get_1d(kWavelengthDimension); });
    const float wavelength = split.wavelength;
    const Color spectral_weight = split.weight;
    if constexpr (kRecord)
        if (split.drawn) recorder_->wavelength(split.u, wavelength);
    const SnellIndices eta = snell_indices(c, media, wavelength);
    const Bsdf bsdf(bsdf_inputs(c, eta));
    if (bsdf.has_smooth_part()) {
        // The smooth parts: the lights straight, the rest from the photons.
        color += next_event_.estimate(c, bsdf, ray.time, stream, stats, /*weigh=*/false,
                                      kRecord ? &record : nullptr);
        int found = 0;
        const Color photons = gather(c, bsdf, found);
        color += photons;
        record.photons = found;
        record.gather_radius = shared_.map ? shared_.map->radius() : 0;
        record.photon_term = photons;
    }
    // The delta parts are followed each whole, a ray tree as Whitted's, while a branch carries at
    // least kSplitWeight of the sample; a lighter one goes on by Russian roulette. Picking one
    // part by its share would leave light that only a rare pick reaches (a lamp seen in glass's
    // 4% reflection) as single bright pixels.
    if constexpr (kRecord) recorder_->path_vertex(c, record);
    Color beyond_color;
    for (const BsdfLobe lobe : {BsdfLobe::reflect, BsdfLobe::transmit}) {
        const std::optional<BsdfSample> s = bsdf.delta_part(lobe);
        if (!s) continue;
        const RayKind kind = s->transmitted ? RayKind::refracted : RayKind::reflected;
        Color factor = s->transmitted ? s->weight * spectral_weight : s->weight;
        const float carried = max_channel(throughput * factor);
        const float survival = carried < kSplitWeight ? carried / kSplitWeight : 1;
        const bool traced = survival >= 1 || stream.next_1d() < survival;
        if constexpr (kRecord)
            recorder_->delta_part(kind, max_channel(s->weight), survival, traced);
        if (!traced) continue;
        if (survival < 1) factor = factor / survival;
        stats.count(kind);
        Ray next = world_.spawn_ray(c.sp.p, c.ng, s->wi, c.sp.error, ray.time);
        next.wavelength = s->transmitted ? wavelength : ray.wavelength;
        MediumStack beyond = media;
        if (s->transmitted)
            beyond = c.entering ? media.entered(c.primitive, &m, ior_at(m, wavelength))
                                : media.left(c.primitive, &m);
        if constexpr (kRecord) recorder_->branch(kind, factor, std::nullopt);
        const auto next_pencil = s->transmitted
                                     ? refraction_pencil(c, ray, pencil, eta.n1 / eta.n2, s->wi)
                                     : mirror_pencil(c, ray, pencil);
        beyond_color += factor * eye_ray<kRecord>(next, depth + 1, beyond, throughput * factor,
                                                  stream, or_null(next_pencil), stats);
    }
    color = through(fade, color + beyond_color);
    if constexpr (kRecord) recorder_->end_ray(color);
    return color;
}

}  // namespace glint
