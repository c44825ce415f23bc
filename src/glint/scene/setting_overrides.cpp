// The overrides: each value's own check, what each replaces, and the settings' joint check.
#include "glint/scene/setting_overrides.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <span>
#include <string_view>

#include "glint/sampling/filter.h"
#include "glint/sampling/sampler.h"
#include "glint/scene/integrators.h"
#include "glint/scene/settings_problem.h"
#include "glint/scene/suggest.h"

namespace glint {

namespace {

void check_range(const char* key, const std::optional<int>& value, int most) {
    if (value) check_whole_number(key, *value, 1, most);
}

// An empty name or one of `names`, else the error that lists them.
void check_name(const char* key, const std::string& name, std::span<const std::string_view> names) {
    if (name.empty() || std::find(names.begin(), names.end(), name) != names.end()) return;
    std::string list;
    for (const std::string_view n : names) list += (list.empty() ? "" : ", ") + std::string(n);
    throw SettingsError(key, std::string(key) + ": unknown name \"" + name + "\"",
                        {std::string(key) + " names are: " + list + did_you_mean(name, names)});
}

}  // namespace

void check_whole_number(const char* key, std::int64_t value, std::int64_t least,
                        std::int64_t most) {
    if (value < least || value > most)
        throw SettingsError(key, std::string(key) + ": expected a whole number from " +
                                     std::to_string(least) + " to " + std::to_string(most) +
                                     ", got " + std::to_string(value));
}

void apply_setting_overrides(const SettingOverrides& o, RenderSettings& s) {
    check_range("width", o.width, kMaxImageSide);
    check_range("height", o.height, kMaxImageSide);
    check_range("spp", o.spp, kMaxSamplesPerPixel);
    check_range("max_depth", o.max_depth, kMaxDepth);
    check_name("integrator", o.integrator, integrator_names());
    check_name("sampler", o.sampler, sampler_names());
    check_name("filter", o.filter, filter_names());
    check_name("shadows", o.shadows, kShadowMethodNames);

    if (o.width && !o.height) {
        s.height =
            std::max(1, static_cast<int>(std::lround(double(*o.width) * s.height / s.width)));
    } else if (o.height && !o.width) {
        s.width =
            std::max(1, static_cast<int>(std::lround(double(*o.height) * s.width / s.height)));
    }
    if (o.width) s.width = *o.width;
    if (o.height) s.height = *o.height;
    // What a front end asks is bounded by the ceilings alone (scene_limits.h).
    if (std::int64_t(s.width) * s.height > kMaxRenderPixels || s.width > kMaxImageSide ||
        s.height > kMaxImageSide)
        throw SettingsError({}, "image of " + std::to_string(s.width) + "x" +
                                    std::to_string(s.height) +
                                    " pixels is larger than the limit of " +
                                    std::to_string(kMaxRenderPixels) + " pixels");
    if (!o.integrator.empty()) s.integrator = *integrator_from_name(o.integrator);
    if (!o.sampler.empty()) s.sampler = *sampler_from_name(o.sampler);
    if (!o.filter.empty()) {
        FilterSpec filter;
        filter.kind = *filter_from_name(o.filter);
        filter.radius = default_filter_radius(filter.kind);
        s.filter = filter;
    }
    if (!o.shadows.empty())
        s.shadows = o.shadows == "map" ? ShadowMethod::map : ShadowMethod::feelers;
    if (o.spp) s.samples_per_pixel = *o.spp;
    if (o.max_depth) s.max_depth = *o.max_depth;
    // The scene file's own checks, on what the overrides made of its settings.
    if (std::optional<SettingsProblem> problem = settings_problem(s))
        throw SettingsError({}, problem->message, std::move(problem->notes));
}

}  // namespace glint
