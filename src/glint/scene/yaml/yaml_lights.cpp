// Reading point and directional lights. `intensity` scales `color`, so that a light's hue and
// strength can be set apart, as in most scene formats.
#include "glint/scene/yaml/yaml_lights.h"

#include <algorithm>
#include <vector>

namespace glint {

namespace {

constexpr Color kWhite{1, 1, 1};

Color read_emitted(const MapReader& map) {
    return map.color("color", kWhite) * map.number("intensity", kNonNegative, 1.0f);
}

Light parse_point(const MapReader& map) {
    PointLight light;
    light.position = map.point("position");
    light.color = read_emitted(map);
    if (const MapEntry* entry = map.find("attenuation")) {
        const YamlSource& source = map.source();
        const auto items = read_sequence(source, entry->value, map.field("attenuation"),
                                         "[constant, linear, quadratic]", 3);
        const char* names[] = {"constant", "linear", "quadratic"};
        float terms[3];
        for (std::size_t i = 0; i < 3; ++i) {
            terms[i] =
                read_number(source, items[i], {map.what(), "attenuation " + std::string(names[i])},
                            kNonNegative);
        }
        // All zero would divide by zero: a light of infinite intensity.
        if (terms[0] == 0 && terms[1] == 0 && terms[2] == 0) {
            throw source.error_at(entry->value,
                                  map.what() + " attenuation must not be all zero, got [0, 0, 0]",
                                  {"[1, 0, 0] is no attenuation; [0, 0, 1] is the inverse "
                                   "square law"});
        }
        light.attenuation = {terms[0], terms[1], terms[2]};
    }
    return light;
}

Light parse_directional(const MapReader& map) {
    DirectionalLight light;
    light.direction = map.direction("direction");
    light.color = read_emitted(map);
    return light;
}

struct LightType {
    std::string_view name;
    std::vector<std::string_view> keys;  // besides type
    Light (*parse)(const MapReader& map);
};

// Sorted by name.
const LightType kLightTypes[] = {
    {"directional", {"direction", "color", "intensity"}, parse_directional},
    {"point", {"position", "color", "intensity", "attenuation"}, parse_point},
};

}  // namespace

Light read_light(const YamlSource& source, const YAML::Node& node, const Field& field) {
    auto entries = read_map(source, node, field);
    std::vector<std::string_view> names;
    for (const LightType& type : kLightTypes) names.push_back(type.name);
    const std::string name = read_type(source, node, entries, "light", names);
    const LightType& type = *std::find_if(std::begin(kLightTypes), std::end(kLightTypes),
                                          [&](const LightType& t) { return t.name == name; });
    std::vector<std::string_view> keys = type.keys;
    keys.push_back("type");
    return type.parse(MapReader(source, node, std::move(entries), name + " light", keys));
}

}  // namespace glint
