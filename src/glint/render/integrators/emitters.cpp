// Emitters by power: each light's light_power (0 for one whose power is not finite, which the
// particles' integrators refuse before a render), each emitting object's, the sky's.
#include "glint/render/integrators/emitters.h"

#include <cmath>
#include <vector>

namespace glint {

Emitters::Emitters(const World& world)
    : world_(world), scene_{world.scene_center(), world.scene_radius()} {
    std::vector<float> power;
    for (const Light& light : world.lights())
        power.push_back(emits_finite_power(light) ? mean(light_power(light, scene_.radius)) : 0);
    for (const ObjectLight& light : world.object_lights())
        power.push_back(mean(object_light_power(light)));
    power.push_back(mean(sky_power(world.sky(), scene_)));
    float total = 0;
    for (float& p : power) {
        if (!std::isfinite(p) || p < 0) p = 0;
        total += p;
    }
    if (total > 0) pick_ = std::make_shared<const DiscreteDistribution>(power);
}

EmittedParticle Emitters::emit(float u_pick, Point2 u_position, Point2 u_direction) const {
    const std::size_t index = pick_->sample(u_pick);
    const auto lights = world_.lights();
    const auto objects = world_.object_lights();
    EmittedParticle e;
    if (index < lights.size())
        e = emit_particle(lights[index], u_position, u_direction, scene_);
    else if (index < lights.size() + objects.size())
        e = emit_particle(objects[index - lights.size()], u_position, u_direction);
    else
        e = emit_sky_particle(world_.sky(), u_position, u_direction, scene_);
    e.power = e.power / pick_->probability(index);
    return e;
}

}  // namespace glint
