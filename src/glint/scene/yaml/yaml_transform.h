// The `transform` key every object takes: a list of steps, applied in the order written.
// Internal to glint_scene.
#pragma once

#include <memory>

#include "glint/math/animated_transform.h"
#include "glint/math/transform.h"
#include "glint/scene/yaml/yaml_reader.h"

namespace glint {

// Steps: {translate: [x, y, z]}, {rotate: {axis: [x, y, z], angle: degrees}},
// {rotate: [rx, ry, rz]} (degrees about x, then y, then z), {scale: s or [sx, sy, sz]} (non-zero),
// {matrix: [[4 numbers] x 4]} (affine: the last row is [0, 0, 0, 1]; invertible).
// The result maps object space to world space: the first step is applied first.
Transform read_transform(const YamlSource& source, const YAML::Node& node, const Field& field);

// The `motion` key: a list of at least two keyframes {time: t, transform: [steps]} (the
// transform defaults to none), times strictly increasing; between them the object moves by
// interpolation (see AnimatedTransform).
std::shared_ptr<const AnimatedTransform> read_motion(const YamlSource& source,
                                                     const YAML::Node& node, const Field& field);

}  // namespace glint
