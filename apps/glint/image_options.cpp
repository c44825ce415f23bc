// The image options as the command line takes them; the library applies and checks them.
#include "image_options.h"

#include <CLI/CLI.hpp>

#include "glint/sampling/sampler.h"
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
    try {
        apply_setting_overrides(c, s);
    } catch (const SettingsError& e) {
        std::string text =
            "the scene's image settings with" + image_options_arguments(c) + ": " + e.what();
        for (const std::string& note : e.notes()) text += " (" + note + ")";
        throw UsageError{text};
    }
}

}  // namespace glint::cli
