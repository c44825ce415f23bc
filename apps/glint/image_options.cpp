// The image options: what each overrides, and the checks the scene's own settings also pass.
#include "image_options.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "glint/sampling/sampler.h"
#include "glint/scene/settings_problem.h"
#include "usage_error.h"
#include "whole_number_option.h"

namespace glint::cli {

namespace {

std::vector<std::string> names(std::span<const std::string_view> list) {
    return {list.begin(), list.end()};
}

}  // namespace

void add_image_options(CLI::App& command, ImageOptions& c) {
    command.add_option("--width", c.width, "Image width in pixels (keeps the aspect alone)")
        ->check(whole_number(1, kMaxImageSide));
    command.add_option("--height", c.height, "Image height in pixels (keeps the aspect alone)")
        ->check(whole_number(1, kMaxImageSide));
    command
        .add_option("--spp", c.spp, "Samples per pixel (a square number for the regular sampler)")
        ->check(whole_number(1, kMaxSamplesPerPixel));
    command.add_option("--integrator", c.integrator, "Integrator, overriding the scene's")
        ->check(CLI::IsMember(names(integrator_names())));
    command.add_option("--sampler", c.sampler, "Sampler, overriding the scene's")
        ->check(CLI::IsMember(names(sampler_names())));
    command.add_option("--filter", c.filter, "Reconstruction filter with its default radius")
        ->check(CLI::IsMember(names(filter_names())));
    command
        .add_option("--shadows", c.shadows, "Shadow feelers or shadow maps, overriding the scene's")
        ->check(CLI::IsMember(names(kShadowMethodNames)));
    command
        .add_option("--max-depth", c.max_depth, "Deepest level of the ray tree (eye rays are 1)")
        ->check(whole_number(1, kMaxDepth));
}

std::string image_options_arguments(const ImageOptions& o) {
    std::string line;
    const auto number = [&](const char* name, const std::optional<int>& value) {
        if (value) line += std::string(" ") + name + " " + std::to_string(*value);
    };
    const auto word = [&](const char* name, const std::string& value) {
        if (!value.empty()) line += std::string(" ") + name + " " + value;
    };
    number("--width", o.width);
    number("--height", o.height);
    number("--spp", o.spp);
    word("--integrator", o.integrator);
    word("--sampler", o.sampler);
    word("--filter", o.filter);
    word("--shadows", o.shadows);
    number("--max-depth", o.max_depth);
    return line;
}

void apply_image_options(const ImageOptions& c, RenderSettings& s) {
    if (c.width && !c.height) {
        s.height =
            std::max(1, static_cast<int>(std::lround(double(*c.width) * s.height / s.width)));
    } else if (c.height && !c.width) {
        s.width =
            std::max(1, static_cast<int>(std::lround(double(*c.height) * s.width / s.height)));
    }
    if (c.width) s.width = *c.width;
    if (c.height) s.height = *c.height;
    // What the command line asks is bounded by the ceilings alone (scene_limits.h).
    if (std::int64_t(s.width) * s.height > kMaxRenderPixels || s.width > kMaxImageSide ||
        s.height > kMaxImageSide)
        throw UsageError{"image of " + std::to_string(s.width) + "x" + std::to_string(s.height) +
                         " pixels is larger than the limit of " + std::to_string(kMaxRenderPixels) +
                         " pixels"};
    if (!c.integrator.empty()) s.integrator = *integrator_from_name(c.integrator);
    if (!c.sampler.empty()) s.sampler = *sampler_from_name(c.sampler);
    if (!c.filter.empty()) {
        FilterSpec filter;
        filter.kind = *filter_from_name(c.filter);
        filter.radius = default_filter_radius(filter.kind);
        s.filter = filter;
    }
    if (!c.shadows.empty())
        s.shadows = c.shadows == "map" ? ShadowMethod::map : ShadowMethod::feelers;
    if (c.spp) s.samples_per_pixel = *c.spp;
    if (c.max_depth) s.max_depth = *c.max_depth;
    // The scene file's own checks, on what the options made of its settings.
    if (const std::optional<SettingsProblem> problem = settings_problem(s)) {
        std::string text = "the scene's image settings with" + image_options_arguments(c) + ": " +
                           problem->message;
        for (const std::string& note : problem->notes) text += " (" + note + ")";
        throw UsageError{text};
    }
}

}  // namespace glint::cli
