// `glint merge` from start to end: read every part's saved state, check that they are the parts
// of one render, each once and finished, add them into the whole's state, write its image.
#include "merge_command.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "command_errors.h"
#include "glint/render/render_output.h"
#include "glint/render/render_part.h"
#include "glint/render/resume_file.h"
#include "output_path.h"
#include "render_summary.h"
#include "usage_error.h"

namespace glint::cli {

namespace {

std::string in_quotes(const std::string& s) { return "\"" + s + "\""; }

// The output named by the parts' files, or the -o given.
std::string merged_output(const MergeCommand& c) {
    if (!c.output.empty()) return c.output;
    const auto output = output_of_part_file(c.parts.front());
    if (!output)
        throw UsageError{"cannot tell the image to write from " + in_quotes(c.parts.front()) +
                         " (a part's file is named <output>.partIofN): give it with -o"};
    return output->string();
}

// Refuses parts that are not, each once, the finished parts of one render; names the
// first part that differs from the first and how.
void check_parts(const std::vector<std::string>& files, const std::vector<SavedRender>& parts) {
    const RenderIdentity& first = parts.front().identity;
    const RenderPart& split = first.part;
    std::map<int, std::string> seen;  // part index -> its file
    for (std::size_t i = 0; i < parts.size(); ++i) {
        const RenderIdentity& id = parts[i].identity;
        if (id.part.count != split.count || id.part.split != split.split)
            throw UsageError{"cannot merge " + in_quotes(files[i]) + " with " +
                             in_quotes(files[0]) + ": it is " + describe(id.part) + ", and that " +
                             describe(split) + ": the parts of one render are split alike"};
        RenderIdentity same_part = id;
        same_part.part = first.part;
        if (const std::string why = identity_difference(same_part, first); !why.empty())
            throw UsageError{"cannot merge " + in_quotes(files[i]) + " with " +
                             in_quotes(files[0]) + ": it was " + why};
        if (const auto [at, fresh] = seen.emplace(id.part.index, files[i]); !fresh)
            throw UsageError{"cannot merge: " + in_quotes(at->second) + " and " +
                             in_quotes(files[i]) + " are both " + describe(id.part)};
        const int passes = pass_count(id.samples_per_pixel, id.pass_size);
        if (!part_done(parts[i].state, id.part, passes))
            throw UsageError{in_quotes(files[i]) + " is " + describe(id.part) +
                             ", unfinished: continue it with glint render ... --resume"};
    }
    for (int index = 1; index <= split.count; ++index)
        if (!seen.contains(index)) {
            RenderPart missing = split;
            missing.index = index;
            throw UsageError{"cannot merge: " + describe(missing) + " is missing (" +
                             std::to_string(parts.size()) + " of " + std::to_string(split.count) +
                             " parts given)"};
        }
}

}  // namespace

const CLI::App* add_merge_command(CLI::App& app, MergeCommand& c) {
    CLI::App* merge = app.add_subcommand(
        "merge", "Write the image of a render made in parts (glint render --part I/N)");
    merge->add_option("parts", c.parts, "The parts' files (<output>.partIofN), every part once")
        ->required();
    merge->add_option("-o,--output", c.output,
                      "Image to write (.png, .ppm, .pfm or .exr); default: the output the "
                      "parts were rendered for");
    merge->add_flag("--ppm-ascii", c.ppm_ascii, "Write .ppm images as ASCII (P3), not binary (P6)");
    merge->add_flag("-q,--quiet", c.quiet, "No summary");
    return merge;
}

int run_merge(const MergeCommand& command) {
    return reporting_errors([&] {
        const std::string output = merged_output(command);
        if (const auto reason = unwritable_image_reason(output)) throw UsageError{*reason};
        std::vector<SavedRender> parts;
        for (const std::string& file : command.parts) parts.push_back(read_saved_render(file));
        check_parts(command.parts, parts);
        const RenderIdentity identity = parts.front().identity;
        const PartSplit split = identity.part.split;
        // In the order of the parts.
        std::sort(parts.begin(), parts.end(), [](const SavedRender& a, const SavedRender& b) {
            return a.identity.part.index < b.identity.part.index;
        });
        std::vector<RenderState> states;
        for (SavedRender& part : parts) states.push_back(std::move(part.state));
        const RenderState whole = merge_parts(std::move(states), split, identity.tile_size);

        RenderResult result;
        result.image = resolve_image(whole);
        result.rays = whole.rays;
        result.bad_samples = whole.bad_samples;
        result.seconds = whole.seconds;
        write_image_and_aovs(output, result, command.ppm_ascii);
        if (result.bad_samples.count > 0)
            std::fprintf(stderr,
                         "glint: warning: %llu samples were NaN or infinite and were left out\n",
                         static_cast<unsigned long long>(result.bad_samples.count));
        if (!command.quiet)
            print_summary(output, settings_of(identity), result,
                          "from " + std::to_string(identity.part.count) + " parts by " +
                              std::string(kPartSplitNames[std::size_t(split)]) +
                              ", their render times added");
        return 0;
    });
}

}  // namespace glint::cli
