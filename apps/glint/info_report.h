// Everything `glint info` reports on a scene, and its two forms: text for a reader, JSON for
// scripts (the keys are documented in docs/cli.md).
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "glint/accel/accel_stats.h"
#include "glint/scene/lint.h"
#include "glint/scene/scene.h"
#include "glint/scene/scene_summary.h"

namespace glint::cli {

struct InfoReport {
    std::string scene;  // the file, as given
    RenderSettings settings;
    SceneSummary summary;
    std::string_view accel;  // the structure's name
    AccelStats accel_stats;
    std::vector<LintWarning> warnings;
};

std::string info_text(const InfoReport& report);
std::string info_json(const InfoReport& report);

}  // namespace glint::cli
