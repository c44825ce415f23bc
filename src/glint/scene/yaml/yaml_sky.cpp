// The sky's image is read as textures are: relative to the scene file, inside the sandbox, its
// values finite and non-negative.
#include "glint/scene/yaml/yaml_sky.h"

#include <memory>
#include <string>

#include "glint/image/image_error.h"
#include "glint/image/texture_file.h"
#include "glint/math/constants.h"
#include "glint/scene/yaml/yaml_file_path.h"
#include "glint/scene/yaml/yaml_reader.h"

namespace glint {

SkyImage read_sky(const YamlSource& source, const ReadSandbox& sandbox, const YAML::Node& node,
                  const Field& field) {
    const MapReader map(source, node, field, "sky", {"file", "rotation", "intensity"});
    SkyImage sky;
    sky.rotation = map.number("rotation", kAnyNumber, 0.0f) * (kPi / 180);
    sky.scale = map.color("intensity", sky.scale);
    const MapEntry& file = map.require("file");
    const std::string name = read_string(source, file.value, map.field("file"));
    const auto path = scene_file_path(source, sandbox, file.value, name, "sky image");
    try {
        record_read(sandbox, path);
        sky.image = std::make_shared<const Image>(load_texture_image(
            path, sandbox.file_limit(kMaxTextureFileBytes), sandbox.limits.image_pixels));
    } catch (const ImageError& e) {
        throw source.error_at(file.value, "cannot read sky image " + quote(name) + ": " + e.detail,
                              {"looked for " + path.string()});
    }
    return sky;
}

}  // namespace glint
