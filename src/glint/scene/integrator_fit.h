// What a scene must offer the integrator that renders it beyond its settings: the light
// integrator's particles carry a share of each light's power, which a light whose intensity does
// not fall off as 1 / d^2 does not have, and reach the eye through its lens, which an
// orthographic camera does not offer; beams sweep planar polygons only, from a pinhole. Checked
// after the command line (or any front end) has chosen the integrator, at the light's, object's
// or material's place in the file.
#pragma once

#include <optional>
#include <string>

#include "glint/scene/scene.h"
#include "glint/scene/scene_error.h"

namespace glint {

// Throws SceneError, located where the loader kept the light's place, when the scene's
// integrator cannot render it.
void check_integrator_fits(const Scene& scene);

// What in a shape beam tracing cannot take ("a sphere, which is curved", "an infinite plane",
// "a CSG object", "a moving object"), or nothing for polygons, triangles, meshes and boxes,
// transformed or not.
std::optional<std::string> beam_unfit_part(const Shape& shape);

}  // namespace glint
