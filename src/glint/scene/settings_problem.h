// The checks that tie a render's settings together (a sample count the sampler can take, what
// adaptive sampling needs), made once for every way a setting arrives: the scene file, the
// command line, and every later front end, so that none of them gets round one.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "glint/scene/scene.h"

namespace glint {

struct SettingsProblem {
    // The setting to blame, as a scene file's `image` map names it: "samples", "sampler",
    // "adaptive", "adaptive.min_samples".
    std::string_view key;
    std::string message;             // what is wrong, with the values
    std::vector<std::string> notes;  // why, or what would do
};

// The first problem of the settings as a whole; nothing when they can be rendered.
std::optional<SettingsProblem> settings_problem(const RenderSettings& settings);

}  // namespace glint
