// Resolving a file a YAML scene names against the scene's folder, and refusing it at its YAML
// node when it leads outside the sandbox.
#include "glint/scene/yaml/yaml_file_path.h"

namespace glint {

std::filesystem::path scene_file_path(const YamlSource& source, const ReadSandbox& sandbox,
                                      const YAML::Node& node, const std::string& name,
                                      std::string_view what) {
    // An absolute name replaces the folder; the sandbox check below judges where it leads.
    const auto path = std::filesystem::path(source.file_name()).parent_path() / name;
    if (const auto refusal = check_read(sandbox, path, what, name))
        throw source.error_at(node, refusal->message, refusal->notes);
    return path;
}

}  // namespace glint
