// The figures of a render as one JSON object, for scripts (`glint render --stats FILE.json`).
// The keys are documented in docs/cli.md.
#pragma once

#include <string>

#include "glint/render/render.h"
#include "phase_times.h"

namespace glint::cli {

struct RenderReport {
    std::string scene;
    std::string output;
    int width = 0, height = 0, samples_per_pixel = 0, threads = 0;
    const RenderResult* result = nullptr;
    PhaseTimes phases;           // outside the render
    double process_seconds = 0;  // since glint started, to the report
};

std::string stats_json(const RenderReport& report);

}  // namespace glint::cli
