// The options that override a scene's image settings, shared by the verbs that trace it
// (`render`, `explain`): an explained sample is the rendered one only under the same settings.
#pragma once

#include <optional>
#include <string>

#include "cli_app_forward.h"
#include "glint/scene/scene.h"
#include "glint/scene/setting_overrides.h"

namespace glint::cli {

using ImageOptions = SettingOverrides;

void add_image_options(CLI::App& command, ImageOptions& options);

// The options as a command line gives them, each after a space: " --width 320 --spp 4".
std::string image_options_arguments(const ImageOptions& options);

// The scene's settings with the options applied (apply_setting_overrides); its SettingsError
// becomes a UsageError that names the options.
void apply_image_options(const ImageOptions& options, RenderSettings& settings);

}  // namespace glint::cli
