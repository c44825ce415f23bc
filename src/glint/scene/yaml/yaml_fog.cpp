// Fogs are checked as they are read: a positive distance and altitude, fractions in [0, 1].
#include "glint/scene/yaml/yaml_fog.h"

#include <array>
#include <string>
#include <string_view>

#include "glint/scene/yaml/yaml_reader.h"

namespace glint {

namespace {

constexpr std::array<std::string_view, 2> kFogKinds = {"constant", "ground"};  // sorted

Fog read_fog(const YamlSource& source, const YAML::Node& node, const Field& field) {
    const MapReader map(source, node, field, "fog",
                        {"color", "distance", "filter", "transmit", "type", "offset", "altitude",
                         "up", "turbulence", "turbulence_depth"});
    Fog fog;
    fog.color = map.color("color", fog.color);
    fog.distance = map.number("distance", kPositive);
    fog.filter = map.number("filter", kUnitInterval, fog.filter);
    fog.transmit = map.number("transmit", kUnitInterval, fog.transmit);
    const bool ground =
        map.choice("type", kFogKinds, "fog type", "fog types", "constant") == "ground";
    fog.kind = ground ? FogKind::ground : FogKind::constant;
    for (const std::string_view key : {"offset", "altitude", "up"})
        if (const MapEntry* entry = map.find(key); entry && !ground)
            throw source.error_at(entry->key_node,
                                  "fog " + std::string(key) + " is for ground fog (type: ground)");
    fog.offset = map.number("offset", kAnyNumber, fog.offset);
    fog.altitude = map.number("altitude", kPositive, fog.altitude);
    fog.up = map.direction("up", fog.up);
    fog.turbulence = map.vector("turbulence", fog.turbulence);
    fog.turbulence_depth = map.number("turbulence_depth", kNonNegative, fog.turbulence_depth);
    return fog;
}

}  // namespace

std::vector<Fog> read_fogs(const YamlSource& source, const YAML::Node& node, const Field& field) {
    if (!node.IsSequence()) return {read_fog(source, node, field)};
    std::vector<Fog> fogs;
    const auto items = read_sequence(source, node, field, "a list of fogs");
    for (std::size_t i = 0; i < items.size(); ++i)
        fogs.push_back(read_fog(source, items[i], {"", field.key + "[" + std::to_string(i) + "]"}));
    return fogs;
}

}  // namespace glint
