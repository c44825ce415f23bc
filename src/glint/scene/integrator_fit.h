// What a scene must offer the integrator that renders it beyond its settings: the light
// integrator's particles carry a share of each light's power, which a light whose intensity does
// not fall off as 1 / d^2 does not have, and reach the eye through its lens, which an
// orthographic camera does not offer. Checked after the command line (or any front end) has
// chosen the integrator, at the light's place in the file.
#pragma once

#include "glint/scene/scene.h"
#include "glint/scene/scene_error.h"

namespace glint {

// Throws SceneError, located where the loader kept the light's place, when the scene's
// integrator cannot render it.
void check_integrator_fits(const Scene& scene);

}  // namespace glint
