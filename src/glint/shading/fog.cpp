// Fog's optical depth in closed form: constant fog's is length / distance; ground fog's density
// 1 / (1 + u^2) above its offset has the antiderivative atan(u) (Barish's ground fog, POV-Ray).
#include "glint/shading/fog.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "glint/shading/noise.h"

namespace glint {

namespace {

constexpr double kEndless = std::numeric_limits<double>::infinity();

// Ground fog's density at the height u (in altitudes over its offset), and its antiderivative.
double ground_density(double u) { return u <= 0 ? 1 : 1 / (1 + u * u); }
double ground_integral(double u) { return u <= 0 ? u : std::atan(u); }

// The integral of the ground fog's density along the stretch, in scene units.
double ground_length(const Fog& fog, const Ray& ray, double length) {
    const Vector3 o{ray.origin.x, ray.origin.y, ray.origin.z};
    const double u0 = (double(dot(o, fog.up)) - fog.offset) / fog.altitude;
    const double du = double(dot(ray.direction, fog.up)) / fog.altitude;  // per unit of length
    if (length == kEndless) {
        // Upwards the density falls as 1 / u^2 and its integral stays finite; level or
        // downwards the stretch stays in fog for ever.
        if (du <= 0) return kEndless;
        return (std::numbers::pi / 2 - ground_integral(u0)) / du;
    }
    const double u1 = u0 + du * length;
    // Nearly level: the difference of the antiderivatives would lose its digits.
    if (std::abs(u1 - u0) < 1e-6) return length * ground_density(0.5 * (u0 + u1));
    return (ground_integral(u1) - ground_integral(u0)) / du;
}

}  // namespace

double optical_depth(const Fog& fog, const Ray& ray, double length) {
    const double in_fog = fog.kind == FogKind::ground ? ground_length(fog, ray, length) : length;
    double tau = in_fog / fog.distance;
    const bool turbulent = fog.turbulence != Vector3{0, 0, 0};
    if (turbulent && length != kEndless) {
        // Noise at the stretch's middle thins the fog there; the further the stretch reaches,
        // the less it shows (POV-Ray's rule), so that distant fog stays smooth.
        const Point3 middle = ray.at(float(0.5 * length));
        const Point3 p{middle.x * fog.turbulence.x, middle.y * fog.turbulence.y,
                       middle.z * fog.turbulence.z};
        const double reach = std::exp(-length / fog.distance);
        tau *= 1 - reach * std::min(1.0, double(turbulence(p, 6)) * fog.turbulence_depth);
    }
    return tau;
}

FogEffect fog_effect(std::span<const Fog> fogs, const Ray& ray, double length) {
    FogEffect effect;
    for (const Fog& fog : fogs) {
        const double tau = optical_depth(fog, ray, length);
        const float t = std::max(float(std::exp(-tau)), fog.transmit);
        effect.transmittance *= t * (Color::gray(1 - fog.filter) + fog.filter * fog.color);
        effect.added += (1 - t) * fog.color;
    }
    return effect;
}

}  // namespace glint
