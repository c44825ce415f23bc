// What a front end overrides of a scene's settings (the command line's --width, --spp, ...;
// Python's render(width=, spp=, ...)), checked once here for all of them: each value against
// its range and names, then the settings as a whole as a scene file's own are.
#pragma once

#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "glint/scene/scene.h"

namespace glint {

struct SettingOverrides {
    std::optional<int> width, height, spp, max_depth;
    std::string integrator;  // empty: the scene's
    std::string sampler;     // empty: the scene's (or its integrator's default)
    std::string filter;      // empty: likewise; else a filter's name with its default radius
    std::string shadows;     // empty: the scene's; else feelers or map
};

// A setting that cannot be rendered. `key` is the override at fault by its field's name
// ("width", "spp", "integrator"), or empty when the settings as a whole are (a sample count the
// sampler cannot take with the scene's sampler, say), which only the front end can word.
class SettingsError : public std::runtime_error {
public:
    SettingsError(std::string key, const std::string& message, std::vector<std::string> notes = {})
        : std::runtime_error(message), key_(std::move(key)), notes_(std::move(notes)) {}
    const std::string& key() const { return key_; }
    const std::vector<std::string>& notes() const { return notes_; }

private:
    std::string key_;
    std::vector<std::string> notes_;
};

// Throws SettingsError for a value of `key` outside [least, most]:
// "spp: expected a whole number from 1 to 16777216, got 0".
void check_whole_number(const char* key, std::int64_t value, std::int64_t least, std::int64_t most);

// The scene's settings with the overrides applied; a lone width or height keeps the scene's
// aspect ratio. Throws SettingsError for a value out of its range or an unknown name, for an
// image over the limits, and for settings that a scene file could not hold either
// (settings_problem: a sample count the sampler cannot take, adaptive sampling with the regular
// sampler or below its min_samples, shadow maps for an integrator that traces its shadows).
void apply_setting_overrides(const SettingOverrides& overrides, RenderSettings& settings);

}  // namespace glint
