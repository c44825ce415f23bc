// The emitters particles and photons leave from, as one list picked in proportion to power:
// world.lights() (those whose power is finite), world.object_lights(), then the sky when it is
// not black.
#pragma once

#include <cstddef>
#include <memory>

#include "glint/render/world.h"
#include "glint/sampling/discrete_distribution.h"
#include "glint/shading/emission.h"

namespace glint {

class Emitters {
public:
    explicit Emitters(const World& world);

    // Whether anything emits.
    bool any() const { return pick_ != nullptr; }
    const SceneSphere& scene() const { return scene_; }

    // A particle of the emitter u_pick picks, its power divided by the probability it was
    // picked with: the flux it carries for the whole scene. any() must hold.
    EmittedParticle emit(float u_pick, Point2 u_position, Point2 u_direction) const;
    // The index of the emitter u_pick picks: world.lights(), then world.object_lights(), then
    // the sky.
    std::size_t picked(float u_pick) const { return pick_->sample(u_pick); }

private:
    const World& world_;
    SceneSphere scene_;
    std::shared_ptr<const DiscreteDistribution> pick_;
};

}  // namespace glint
