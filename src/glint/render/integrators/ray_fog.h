// What the medium a ray travels through does to the light it brings back, from its origin to
// what it meets (kInfinity: the sky): fog outside objects, and inside a transparent object its
// interior fade. Fog stays out of objects, as POV-Ray keeps it out of its solid (not hollow) ones.
#pragma once

#include <optional>

#include "glint/render/integrators/medium_stack.h"
#include "glint/render/world.h"
#include "glint/shading/fog.h"
#include "glint/shading/interior_fade.h"
#include "glint/shading/material.h"

namespace glint {

// The fade of the object the ray travels inside over `length`, as a fog that adds no light;
// none outside objects or inside one that does not fade.
inline std::optional<FogEffect> interior_fade(const MediumStack& media, float length) {
    if (media.size() == 0) [[likely]]
        return std::nullopt;
    const InteriorFade& fade = media.innermost_material()->fade;
    if (!fade.fades()) return std::nullopt;
    return FogEffect{fade_over(fade, length), {}};
}

// None when the ray meets neither fog nor fade.
inline std::optional<FogEffect> ray_fog(const World& world, const Ray& ray,
                                        const MediumStack& media, float length) {
    if (media.size() > 0) [[unlikely]]
        return interior_fade(media, length);
    if (world.fogs().empty()) [[likely]]
        return std::nullopt;
    return fog_effect(world.fogs(), ray, length);
}

}  // namespace glint
