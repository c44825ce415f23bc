// Reading lights. `intensity` scales `color`, so that a light's hue and strength can be set
// apart, as in most scene formats. Area lights may be seen: their face becomes an object.
#include "glint/scene/yaml/yaml_lights.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

#include "glint/geometry/moving.h"
#include "glint/math/constants.h"
#include "glint/scene/animation.h"
#include "glint/scene/scene.h"
#include "glint/scene/yaml/yaml_transform.h"

namespace glint {

namespace {

constexpr Color kWhite{1, 1, 1};

Color read_emitted(const MapReader& map) {
    return map.color("color", kWhite) * map.number("intensity");
}

Attenuation read_attenuation(const MapReader& map) {
    const MapEntry* entry = map.find("attenuation");
    if (!entry) return {};
    const YamlSource& source = map.source();
    const auto items = read_sequence(source, entry->value, map.field("attenuation"),
                                     "[constant, linear, quadratic]", 3);
    const char* names[] = {"constant", "linear", "quadratic"};
    float terms[3];
    for (std::size_t i = 0; i < 3; ++i) {
        terms[i] = read_number(source, items[i],
                               {map.what(), "attenuation " + std::string(names[i])}, kNonNegative);
    }
    // All zero would divide by zero: a light of infinite intensity.
    if (terms[0] == 0 && terms[1] == 0 && terms[2] == 0) {
        throw source.error_at(entry->value,
                              map.what() + " attenuation must not be all zero, got [0, 0, 0]",
                              {"[1, 0, 0] is no attenuation; [0, 0, 1] is the inverse "
                               "square law"});
    }
    return {terms[0], terms[1], terms[2]};
}

LightEntry parse_point(const MapReader& map) {
    PointLight light;
    light.position = map.point("position");
    light.color = read_emitted(map);
    light.attenuation = read_attenuation(map);
    light.casts_shadows = map.boolean("shadows", true);
    light.in_media = map.boolean("in_media", true);
    return {light, std::nullopt};
}

LightEntry parse_spot(const MapReader& map) {
    SpotLight light;
    light.position = map.point("position");
    const YamlSource& source = map.source();
    // The axis: a direction, or a point the spot is aimed at.
    const std::string both_note = "direction is the way the cone points; at is a point it aims at";
    if (!map.has("direction") && !map.has("at"))
        throw source.error_at(map.node(), "spot light needs \"direction\" or \"at\"", {both_note});
    if (map.has("direction") && map.has("at")) {
        throw source.error_at(map.require("at").key_node,
                              "spot light takes \"direction\" or \"at\", not both", {both_note});
    }
    if (map.has("direction")) {
        light.direction = map.direction("direction");
    } else {
        const auto axis = unit_vector(map.point("at") - light.position);
        if (!axis) {
            throw source.error_at(map.require("at").value,
                                  "spot light at must differ from its position, both are " +
                                      format_vector(to_vector(light.position)));
        }
        light.direction = *axis;
    }
    const float cone = map.number("cone_angle");
    const float falloff = map.number_or("falloff", std::min(5.0f, cone));
    if (falloff > cone) {
        throw source.error_at(
            map.require("falloff").value,
            "spot light falloff must not exceed its cone_angle (" + format_number(cone) +
                "), got " + format_number(falloff),
            {"falloff is the width, in degrees, of the soft rim inside the cone"});
    }
    light.cos_cone = std::cos(radians(cone));
    light.cos_falloff = std::cos(radians(cone - falloff));
    light.tightness = map.number_or("tightness", 0);
    light.color = read_emitted(map);
    light.attenuation = read_attenuation(map);
    light.casts_shadows = map.boolean("shadows", true);
    light.in_media = map.boolean("in_media", true);
    return {light, std::nullopt};
}

LightEntry parse_directional(const MapReader& map) {
    DirectionalLight light;
    light.direction = map.direction("direction");
    light.color = read_emitted(map);
    light.casts_shadows = map.boolean("shadows", true);
    light.in_media = map.boolean("in_media", true);
    return {light, std::nullopt};
}

// What every area light takes besides its shape.
LightEntry area_light(const MapReader& map, AreaLight light) {
    light.color = read_emitted(map);
    light.attenuation = read_attenuation(map);
    light.shadow_rays = map.integer_or("shadow_rays", 0);
    light.casts_shadows = map.boolean("shadows", true);
    light.in_media = map.boolean("in_media", true);
    LightEntry entry{light, std::nullopt};
    if (map.boolean("visible", true))
        entry.visible_shape =
            std::visit([](const auto& shape) { return Shape(shape); }, light.shape);
    return entry;
}

LightEntry parse_sphere(const MapReader& map) {
    const Point3 center = map.point("center");
    return area_light(map, sphere_light(center, map.number("radius")));
}

LightEntry parse_disk(const MapReader& map) {
    const Point3 center = map.point("center");
    const Normal3 normal(map.direction("normal", Vector3{0, -1, 0}));
    return area_light(map, disk_light(center, normal, map.number("radius")));
}

LightEntry parse_rectangle(const MapReader& map) {
    const Point3 center = map.point("center");
    const Vector3 u = map.vector("u"), v = map.vector("v");
    const Vector3 normal = cross(u, v);
    std::optional<AreaLight> light;
    if (length_squared(normal) > 0 && std::isfinite(length_squared(normal)))
        light = rectangle_light(center, u, v);
    if (!light) {
        throw map.source().error_at(
            map.require("v").value,
            "rectangle light sides u and v must be non-zero and not parallel, got u = " +
                format_vector(u) + " and v = " + format_vector(v));
    }
    return area_light(map, std::move(*light));
}

// Their keys are the lights' schemas (scene/schema/light_schemas.cpp).
struct LightType {
    std::string_view name;
    LightEntry (*parse)(const MapReader& map);
};

// Sorted by name.
const LightType kLightTypes[] = {
    {"directional", parse_directional}, {"disk", parse_disk},     {"point", parse_point},
    {"rectangle", parse_rectangle},     {"sphere", parse_sphere}, {"spot", parse_spot},
};

}  // namespace

LightEntry read_light(const YamlSource& source, const YAML::Node& node, const Field& field) {
    auto entries = read_map(source, node, field);
    std::vector<std::string_view> names;
    for (const LightType& type : kLightTypes) names.push_back(type.name);
    const std::string name = read_type(source, node, entries, "light", names);
    const LightType& type = *std::find_if(std::begin(kLightTypes), std::end(kLightTypes),
                                          [&](const LightType& t) { return t.name == name; });
    const MapReader map(source, node, std::move(entries), name + " light",
                        entity_schema(EntityFamily::light, name), {"type"});
    LightEntry entry = type.parse(map);
    if (const MapEntry* motion = map.find("motion")) {
        entry.motion = read_motion(source, motion->value, map.field("motion"));
        const auto& keyframes = entry.motion->keyframes();
        for (std::size_t i = 0; i < keyframes.size(); ++i)
            if (!keeps_shapes(keyframes[i].world_from_object))
                throw source.error_at(motion->value[i],
                                      "a light's keyframes may move, turn and scale it evenly, "
                                      "not stretch or shear it");
        if (entry.visible_shape)
            entry.visible_shape = Moving{
                entry.motion, std::make_shared<const Shape>(std::move(*entry.visible_shape))};
    }
    return entry;
}

}  // namespace glint
