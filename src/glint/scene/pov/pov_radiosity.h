// POV-Ray's radiosity onto glint's path tracer. POV-Ray gathers the light that surfaces reflect
// onto one another at sparse points and interpolates it (Ward's irradiance cache); glint's path
// integrator computes the same integral at every pixel, so the cache's settings have nothing to
// steer and only what changes the light itself is kept.
#pragma once

#include <string>
#include <vector>

#include "glint/scene/pov/pov_item_reader.h"
#include "glint/scene/pov/pov_parser.h"
#include "glint/scene/scene.h"

namespace glint {

// What `global_settings { radiosity { … } }` asks for, read and checked.
struct PovRadiosity {
    double brightness = 1;  // scales the gathered light
};

// The samples a pixel a radiosity scene takes unless the command line says otherwise: a
// square, which every sampler takes, should the command line ask for the whitted integrator.
inline constexpr int kPovRadiositySamples = 36;

// Reads the block after the word `radiosity` (its opening brace next): every setting of
// POV-Ray 3.7's (count, error_bound, pretrace_start, …), each checked as POV-Ray checks it.
PovRadiosity read_pov_radiosity(PovParser& parser, PovItemReader& items);

// Renders `scene` by the path integrator with at least kPovRadiositySamples samples a pixel, as
// POV-Ray renders it with radiosity: the ambient term goes (scene.ambient black), and where the
// scene is older than POV-Ray 3.7 (`legacy`) each surface gives off its ambient term as light
// instead, as POV-Ray 3.6 does. A scene with media keeps its integrator, which marches them.
// What differs from POV-Ray is added to `warnings`.
void light_by_radiosity(const PovRadiosity& radiosity, bool legacy, Scene& scene,
                        std::vector<std::string>& warnings);

}  // namespace glint
