// A camera as text: the `camera` map of glint's YAML format, read by the scene files' own reader
// (a page that moves a scene's camera sends one), and a camera written as one, to paste into a
// scene file.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "glint/camera/camera_spec.h"

namespace glint {

// The camera of a map such as `{from: [0, 2, -8], at: [0, 1, 0], up: [0, 1, 0], fov: 38}` (or its
// JSON), checked as a scene file's camera is. Throws SceneError located in the text, which is
// named `as_file` in messages; keys that do nothing add warnings.
CameraSpec parse_camera_text(std::string_view text, const std::string& as_file,
                             std::vector<std::string>* warnings = nullptr);

// The camera's view as a `camera:` line of a scene file: the projection when not perspective,
// from, at, up and its projection's angle or height, each number as the float it is. The lens
// and shutter are left out: a scene keeps its own.
std::string camera_yaml(const CameraSpec& camera);

}  // namespace glint
