// The choices of a render beside the scene's settings (the acceleration structure and the output
// variables), checked once here for every front end: the command line, Python and the page, so
// that each refuses a value with the same words.
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "glint/accel/make_aggregate.h"
#include "glint/render/film/aov.h"
#include "glint/scene/integrators.h"

namespace glint {

// The structure of that name; throws SettingsError("accel", ...) with a note that lists the
// names this build has.
AccelKind accel_named(std::string_view name);

// The output variables of a comma list of aov.h's names and groups ("depth,normal", "all") for a
// render with `integrator`; throws SettingsError("aovs", ...) for an unknown name or an
// integrator that takes none.
AovSet aovs_named(std::string_view list, IntegratorKind integrator);

// Why `aovs` cannot be recorded by `integrator` (which traces no rays to follow), or nothing.
std::optional<std::string> aovs_problem(const AovSet& aovs, IntegratorKind integrator);

}  // namespace glint
