// The camera map read with the scene files' own reader; written with every float exact.
#include <yaml-cpp/yaml.h>

#include "glint/scene/camera_text.h"
#include "glint/scene/yaml/yaml_reader.h"
#include "glint/scene/yaml/yaml_settings.h"
#include "glint/scene/yaml/yaml_source.h"

namespace glint {

CameraSpec parse_camera_text(std::string_view text, const std::string& as_file,
                             std::vector<std::string>* warnings) {
    const YamlSource source(text, as_file);
    try {
        const YAML::Node root = YAML::Load(std::string(text));
        std::vector<std::string> said;
        CameraSpec camera = read_camera(source, root, Field("", "camera"), said);
        if (warnings) warnings->insert(warnings->end(), said.begin(), said.end());
        return camera;
    } catch (...) {
        rethrow_as_scene_error(source, "the camera");
    }
}

std::string camera_yaml(const CameraSpec& camera) {
    std::string out = "{";
    if (camera.projection != Projection::perspective)
        out += std::string("type: ") + projection_name(camera.projection) + ", ";
    out += "from: " + format_vector(to_vector(camera.from));
    out += ", at: " + format_vector(to_vector(camera.at));
    out += ", up: " + format_vector(camera.up);
    const auto number = [&](const char* key, float value) {
        out += std::string(", ") + key + ": " + format_number(value);
    };
    switch (camera.projection) {
        case Projection::perspective:
        case Projection::fisheye:
        case Projection::ultra_wide_angle:
            number("fov", camera.fov);
            break;
        case Projection::orthographic:
            number("height", camera.height);
            break;
        case Projection::panoramic:
            break;
        case Projection::cylindrical:
            number("fov", camera.fov);
            number("height", camera.height);
            out += camera.cylinder_axis_across ? ", axis: horizontal" : "";
            out += camera.cylinder_parallel ? ", parallel: true" : "";
            break;
        case Projection::spherical:
            number("fov", camera.fov);
            number("vertical_fov", camera.vertical_fov);
            break;
    }
    return out + "}";
}

}  // namespace glint
