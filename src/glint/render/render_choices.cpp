#include "glint/render/render_choices.h"

#include <stdexcept>

#include "glint/scene/setting_overrides.h"

namespace glint {

AccelKind accel_named(std::string_view name) {
    if (const auto kind = accel_from_name(name)) return *kind;
    std::string list;
    for (const std::string_view n : accel_names())
        list += (list.empty() ? "" : ", ") + std::string(n);
    throw SettingsError("accel", "accel: unknown name \"" + std::string(name) + "\"",
                        {"accel names are: " + list});
}

AovSet aovs_named(std::string_view list, IntegratorKind integrator) {
    AovSet set;
    try {
        set = parse_aov_list(list);
    } catch (const std::invalid_argument& e) {
        throw SettingsError("aovs", std::string("aovs: ") + e.what());
    }
    if (const auto problem = aovs_problem(set, integrator))
        throw SettingsError("aovs", "aovs: " + *problem);
    return set;
}

std::optional<std::string> aovs_problem(const AovSet& aovs, IntegratorKind integrator) {
    if (aovs.empty() || traces_rays(integrator)) return std::nullopt;
    const std::string name(integrator_name(integrator));
    return "the output variables follow rays, and the " + name + " integrator traces " + name + "s";
}

}  // namespace glint
