// Participating media in the YAML format: a material's `medium_*` keys, and the `atmosphere`
// section's keys of the same names without the prefix.
#pragma once

#include <optional>
#include <string_view>
#include <vector>

#include "glint/scene/yaml/yaml_map_reader.h"
#include "glint/shading/medium.h"

namespace glint {

// The medium of the map's keys `prefix` + absorption, emission, scattering, phase,
// eccentricity, extinction and samples; none when none of the first three is given (and an
// error when one of the others is).
std::optional<Medium> read_medium(const MapReader& map, std::string_view prefix);

// The `atmosphere` section: one medium.
std::vector<Medium> read_atmosphere(const YamlSource& source, const YAML::Node& node,
                                    const Field& field);

}  // namespace glint
