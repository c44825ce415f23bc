// Ray marching through participating media, with a shadow feeler to each light from each point.
#include "glint/render/integrators/media_marching.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "glint/shading/light.h"

namespace glint {

namespace {

int interval_count(std::span<const Medium> media) {
    int n = 1;
    for (const Medium& m : media) n = std::max(n, m.samples);
    return n;
}

// exp(-x) per channel.
Color transmitted(const Color& depth) {
    return {std::exp(-depth.r), std::exp(-depth.g), std::exp(-depth.b)};
}

// (1 - exp(-x ds)) / x per channel: how much of a constant source over ds reaches its start;
// ds where nothing is extinguished.
Color through_interval(const Color& sigma_t, float ds) {
    const auto channel = [ds](float x) {
        return x * ds > 1e-6f ? -std::expm1(-x * ds) / x : ds * (1 - x * ds / 2);
    };
    return {channel(sigma_t.r), channel(sigma_t.g), channel(sigma_t.b)};
}

}  // namespace

FogEffect march_media(const World& world, ShadowFeelers& feelers, std::span<const Medium> media,
                      const Ray& ray, float length, float offset, RayStats& stats) {
    const int n = interval_count(media);
    const float ds = length / float(n);
    const auto lights = world.lights();
    FogEffect effect;
    for (int i = 0; i < n; ++i) {
        SurfacePoint at;
        at.p = ray.at((float(i) + offset) * ds);
        Color sigma_t, source;
        std::array<Color, kMaxMedia> scattering{};  // each medium's at its density here
        bool scatters = false;
        for (std::size_t k = 0; k < media.size(); ++k) {
            const Color d = density_at(media[k], at.p);
            sigma_t += extinction_of(media[k], d);
            source += d * media[k].emission;
            scattering[k] = d * media[k].scattering;
            scatters = scatters || !is_black(scattering[k]);
        }
        for (std::size_t l = 0; scatters && l < lights.size(); ++l) {
            if (!scatters_in_media(lights[l])) continue;
            const LightSample ls = sample_light(lights[l], at.p);
            if (is_black(ls.intensity)) continue;
            const float cos_theta = dot(ls.to_light, ray.direction);
            Color scattered;  // per unit of the light's
            for (std::size_t k = 0; k < media.size(); ++k)
                scattered +=
                    scattering[k] * phase_value(media[k].phase, media[k].eccentricity, cos_theta);
            if (is_black(scattered)) continue;
            const Color shadow = feelers.transmittance(l, at, Normal3(ls.to_light), ls.to_light,
                                                       ls.distance, ray.time, stats, true);
            source += scattered * ls.intensity * shadow;
        }
        effect.added += effect.transmittance * source * through_interval(sigma_t, ds);
        effect.transmittance *= transmitted(sigma_t * ds);
    }
    return effect;
}

Color media_transmittance(std::span<const Medium> media, const Ray& ray, float length) {
    // A quarter of the points: each point of a marched ray sends a feeler, so that the
    // feelers' points would otherwise grow as the square of the samples.
    const int n = (interval_count(media) + 3) / 4;
    const float ds = length / float(n);
    Color depth;
    for (int i = 0; i < n; ++i) {
        const Point3 p = ray.at((float(i) + 0.5f) * ds);
        for (const Medium& m : media) depth += extinction_of(m, density_at(m, p)) * ds;
    }
    return transmitted(depth);
}

}  // namespace glint
