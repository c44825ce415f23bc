// `glint bench`: every acceleration structure (and Embree, when built with it) on the same ray
// sets of one scene: build time, rays per second at one thread and at all, bytes per primitive.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "scene_read_options.h"

namespace glint::cli {

struct BenchCommand {
    std::string scene;
    bool json = false;                  // one JSON object a line instead of a table
    std::vector<std::string> accels;    // empty: every structure but the brute-force list
    std::vector<std::string> ray_sets;  // empty: all three (primary, incoherent, shadow)
    int threads = 0;                    // the "all threads" count; 0: every core
    std::size_t rays = 1'000'000;       // rays a set
    bool packets = false;               // each set traced in packets of eight as well
    SceneReadOptions reading;           // --allow-read, --max-file-size
};

// Registers the subcommand and its options on app; returns it (to ask whether it was chosen).
CLI::App* add_bench_command(CLI::App& app, BenchCommand& command);

// Exit status: 0 on success, 2 on bad input (scene, options), 1 on any other failure.
int run_bench(const BenchCommand& command);

}  // namespace glint::cli
