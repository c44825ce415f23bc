// A medium's keys, checked as they are read: colours not negative, the eccentricity in (-1, 1),
// the extinction in [0, 1], the samples from 1 to 1000.
#include "glint/scene/yaml/yaml_medium.h"

#include <string>

#include "glint/scene/yaml/yaml_reader.h"

namespace glint {

namespace {

constexpr std::string_view kPhases[] = {"henyey_greenstein", "isotropic", "mie_hazy", "mie_murky",
                                        "rayleigh"};  // sorted

}  // namespace

std::optional<Medium> read_medium(const MapReader& map, std::string_view prefix) {
    const std::string p(prefix);
    const auto key = [&](std::string_view name) { return p + std::string(name); };
    const bool given =
        map.has(key("absorption")) || map.has(key("emission")) || map.has(key("scattering"));
    if (!given) {
        for (const std::string_view other : {"phase", "eccentricity", "extinction", "samples"})
            if (map.has(key(other)))
                throw map.source().error_at(map.require(key(other)).key_node,
                                            key(other) + " needs a medium: give " +
                                                key("absorption") + ", " + key("emission") +
                                                " or " + key("scattering"));
        return std::nullopt;
    }
    Medium medium;
    medium.absorption = map.color(key("absorption"), Color{});
    medium.emission = map.color(key("emission"), Color{});
    medium.scattering = map.color(key("scattering"), Color{});
    const std::string phase =
        map.choice(key("phase"), kPhases, "medium phase", "medium phases", "isotropic");
    medium.phase = phase == "rayleigh"            ? PhaseKind::rayleigh
                   : phase == "mie_hazy"          ? PhaseKind::mie_hazy
                   : phase == "mie_murky"         ? PhaseKind::mie_murky
                   : phase == "henyey_greenstein" ? PhaseKind::henyey_greenstein
                                                  : PhaseKind::isotropic;
    medium.eccentricity =
        map.number(key("eccentricity"), Range{-1, 1, true, true}, medium.eccentricity);
    medium.extinction = map.number(key("extinction"), kUnitInterval, medium.extinction);
    medium.samples = map.integer(key("samples"), IntRange{1, 1000}, medium.samples);
    return medium;
}

std::vector<Medium> read_atmosphere(const YamlSource& source, const YAML::Node& node,
                                    const Field& field) {
    const MapReader map(
        source, node, field, "atmosphere",
        {"absorption", "emission", "scattering", "phase", "eccentricity", "extinction", "samples"});
    std::optional<Medium> medium = read_medium(map, "");
    if (!medium)
        throw source.error_at(node, "atmosphere needs absorption, emission or scattering",
                              {"e.g. atmosphere: {scattering: 0.02}"});
    return {std::move(*medium)};
}

}  // namespace glint
