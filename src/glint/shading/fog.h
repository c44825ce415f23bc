// Fog: depth cueing, as POV-Ray draws it. Along a ray the colour from behind fades towards the
// fog's colour by the fog's transmittance T = exp(-tau), tau the optical depth of the stretch,
// so that what arrives is T * behind + (1 - T) * fog colour: the light of a medium that absorbs
// and glows in its colour, and scatters none. Shadow rays pass through it unchanged.
#pragma once

#include <optional>
#include <span>

#include "glint/math/color.h"
#include "glint/math/ray.h"
#include "glint/math/vector.h"

namespace glint {

enum class FogKind {
    constant,  // the same density everywhere
    // Full density below `offset` along `up`; above it, 1 / (1 + h^2) at the height h over
    // offset, measured in `altitude`s: ground mist that thins out upwards.
    ground,
};

struct Fog {
    Color color{0.5f, 0.5f, 0.5f};
    float distance = 1;  // > 0: the distance along which full-density fog lets exp(-1) through
    // How much of the light that gets through is tinted by the fog's colour (0: none, 1: all).
    float filter = 0;
    float transmit = 0;  // the least of the light behind that always gets through, [0, 1]
    FogKind kind = FogKind::constant;
    float offset = 0;     // ground fog: the height (along up) below which it is full density
    float altitude = 1;   // ground fog: > 0, the height scale of its thinning
    Vector3 up{0, 1, 0};  // unit
    // Turbulence: the optical depth of a stretch varies by noise at its middle point, scaled
    // componentwise by `turbulence` (zero: none), as much as `turbulence_depth` of it.
    Vector3 turbulence{0, 0, 0};
    float turbulence_depth = 0.5f;
};

// What fog does to the colour a ray brings back: arriving = transmittance * behind + added.
struct FogEffect {
    Color transmittance{1, 1, 1};
    Color added;
};

// The optical depth of the stretch of `ray` (unit direction) from t = 0 to `length` (kInfinity
// for a ray that leaves the scene): infinite when the stretch is endless and stays in fog.
double optical_depth(const Fog& fog, const Ray& ray, double length);

// The effect of all the fogs on that stretch. Several fogs combine as POV-Ray combines them:
// the transmittances multiply, the fogs' colours add, each by its own (1 - T).
FogEffect fog_effect(std::span<const Fog> fogs, const Ray& ray, double length);

inline Color through(const FogEffect& effect, Color behind) {
    return effect.transmittance * behind + effect.added;
}

// No fog lets everything through.
inline Color through(const std::optional<FogEffect>& effect, Color behind) {
    return effect ? through(*effect, behind) : behind;
}

}  // namespace glint
