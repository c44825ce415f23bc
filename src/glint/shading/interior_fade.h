// Light fading inside a transparent object (POV-Ray's interior fade): what travels a distance
// d through the object's inside arrives multiplied, per channel c of the fade colour, by
//   exponential (Beer-Lambert):  exp(-(1 - c) d / distance)
//   with a power p:              c + (1 - c) / (1 + (d / distance)^p)
// so that colour c passes unfaded and the rest falls to exp(-1), or to half, at `distance`.
#pragma once

#include <cmath>
#include <string>

#include "glint/math/color.h"

namespace glint {

struct InteriorFade {
    float distance = 0;  // > 0; 0: no fade
    // The power p; kExponential (any p >= 1000 in POV-Ray) for Beer-Lambert's law.
    float power = kExponential;
    Color color;  // what passes unfaded, channels in [0, 1]

    static constexpr float kExponential = 1000;
    bool fades() const { return distance > 0; }
};

// The factor light is multiplied by over the distance d >= 0 (infinite: the limit, c or 0).
inline Color fade_over(const InteriorFade& fade, float d) {
    if (!fade.fades()) return Color{1, 1, 1};
    const float x = d / fade.distance;
    if (fade.power >= InteriorFade::kExponential) {
        // A channel of colour 1 passes whole, even over an infinite distance.
        const auto channel = [x](float c) { return c < 1 ? std::exp(-(1 - c) * x) : 1.0f; };
        return Color{channel(fade.color.r), channel(fade.color.g), channel(fade.color.b)};
    }
    const float kept = 1 / (1 + std::pow(x, fade.power));
    return fade.color + (Color{1, 1, 1} - fade.color) * kept;
}

// What is wrong with the fade's numbers as a scene gave them, or "": the distance >= 0, the
// power >= 0 and the colour's channels in [0, 1] (above 1 light would grow on its way).
inline std::string describe_problem(const InteriorFade& fade) {
    if (!(fade.distance >= 0) || !std::isfinite(fade.distance))
        return "fade distance must be finite and >= 0";
    if (!(fade.power >= 0) || !std::isfinite(fade.power))
        return "fade power must be finite and >= 0";
    for (const float c : {fade.color.r, fade.color.g, fade.color.b})
        if (!(c >= 0 && c <= 1)) return "fade colour's channels must be in [0, 1]";
    return "";
}

}  // namespace glint
