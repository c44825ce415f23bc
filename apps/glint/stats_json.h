// The figures of a render as one JSON object, for scripts (`glint render --stats FILE.json`).
// The keys are documented in docs/cli.md.
#pragma once

#include <string>

#include "glint/render/render.h"

namespace glint::cli {

struct RenderReport {
    std::string scene;
    std::string output;
    int width = 0, height = 0, samples_per_pixel = 0, threads = 0;
    const RenderResult* result = nullptr;
};

std::string stats_json(const RenderReport& report);

}  // namespace glint::cli
