// `glint merge PARTS... -o out.exr`: the image of a render made in parts (`glint render --part`),
// as one run of the whole would write it.
#pragma once

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

namespace glint::cli {

struct MergeCommand {
    std::vector<std::string> parts;  // the parts' files, in any order
    std::string output;              // empty: the parts' output ("out.exr.part1of4" -> out.exr)
    bool quiet = false;
    bool ppm_ascii = false;
};

// Adds the verb to `app`; the returned subcommand is parsed when it was given.
const CLI::App* add_merge_command(CLI::App& app, MergeCommand& command);

// Exit status: 0 on success, 2 when the parts cannot be merged (missing, unfinished, damaged, or
// of different renders: the message names the part and the difference), 1 on other failures.
int run_merge(const MergeCommand& command);

}  // namespace glint::cli
