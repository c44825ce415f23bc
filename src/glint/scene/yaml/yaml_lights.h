// Light sources of the YAML format: point, spot, directional and area lights (sphere, disk,
// rectangle).
#pragma once

#include <memory>
#include <optional>

#include "glint/geometry/shape.h"
#include "glint/math/animated_transform.h"
#include "glint/scene/yaml/yaml_map_reader.h"
#include "glint/shading/light.h"

namespace glint {

struct LightEntry {
    Light light;
    // An area light's face, for the camera and mirrors to see (visible: true): the scene adds it
    // as an object that glows in the light's colour and casts no shadow.
    std::optional<Shape> visible_shape;
    // Keyframes that move the light from frame to frame (and its face with them); none: still.
    std::shared_ptr<const AnimatedTransform> motion;
};

// A light map such as {type: point, position: [0, 5, 0]}.
LightEntry read_light(const YamlSource& source, const YAML::Node& node, const Field& field);

}  // namespace glint
