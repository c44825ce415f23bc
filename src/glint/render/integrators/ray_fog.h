// The fog a ray that carries light to the eye passes through, from its origin to what it meets
// (kInfinity: the sky). Inside a refracting object a ray travels through the object's interior,
// which holds no fog, as POV-Ray keeps fog out of its solid (not hollow) objects.
#pragma once

#include <optional>

#include "glint/render/integrators/medium_stack.h"
#include "glint/render/world.h"
#include "glint/shading/fog.h"

namespace glint {

// None when the scene has no fog or the ray is inside an object.
inline std::optional<FogEffect> ray_fog(const World& world, const Ray& ray,
                                        const MediumStack& media, float length) {
    if (world.fogs().empty() || media.size() > 0) [[likely]]
        return std::nullopt;
    return fog_effect(world.fogs(), ray, length);
}

}  // namespace glint
