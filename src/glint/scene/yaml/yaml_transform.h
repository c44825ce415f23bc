// The `transform` key every object takes: a list of steps, applied in the order written.
// Internal to glint_scene.
#pragma once

#include "glint/math/transform.h"
#include "glint/scene/yaml/yaml_reader.h"

namespace glint {

// Steps: {translate: [x, y, z]}, {rotate: {axis: [x, y, z], angle: degrees}},
// {rotate: [rx, ry, rz]} (degrees about x, then y, then z), {scale: s or [sx, sy, sz]} (non-zero),
// {matrix: [[4 numbers] x 4]} (affine: the last row is [0, 0, 0, 1]; invertible).
// The result maps object space to world space: the first step is applied first.
Transform read_transform(const YamlSource& source, const YAML::Node& node, const Field& field);

}  // namespace glint
