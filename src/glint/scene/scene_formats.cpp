// The formats' table.
#include "glint/scene/scene_formats.h"

#include <algorithm>
#include <cctype>

#include "glint/scene/mesh/model_scene.h"
#include "glint/scene/nff/nff_to_scene.h"
#include "glint/scene/pov/pov_scene.h"
#include "glint/scene/yaml/yaml_scene_loader.h"

namespace glint {

namespace {

constexpr std::string_view kYaml[] = {".yaml", ".yml"};
constexpr std::string_view kNff[] = {".nff", ".nff.gz"};
constexpr std::string_view kModels[] = {".obj", ".ply", ".gltf", ".glb", ".stl"};
constexpr std::string_view kPov[] = {".pov"};

Scene load_nff(const std::filesystem::path& file, const ReadSandbox& sandbox) {
    // An NFF file names no other files: only its own size is checked.
    return load_nff_scene(file, sandbox.file_limit(kMaxNffFileBytes), sandbox.limits);
}

Scene load_yaml(const std::filesystem::path& file, const ReadSandbox& sandbox) {
    return load_yaml_scene(file, sandbox);
}

Scene load_model(const std::filesystem::path& file, const ReadSandbox& sandbox) {
    return load_model_scene(file, sandbox);
}

const SceneFormat kFormats[] = {
    {"glint", kYaml, "glint's format", load_yaml},
    {"NFF", kNff, "Haines' NFF, gzipped or not", load_nff},
    {"model", kModels, "models, through Assimp", load_model},
    {"POV-Ray", kPov, "POV-Ray's scene language: its core, docs/povray.md", load_pov_scene},
};

std::string lower(std::string text) {
    std::transform(text.begin(), text.end(), text.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return text;
}

}  // namespace

std::span<const SceneFormat> scene_formats() { return kFormats; }

const SceneFormat* scene_format_of(const std::filesystem::path& file) {
    const std::string name = lower(file.filename().string());
    const SceneFormat* found = nullptr;
    std::size_t longest = 0;  // ".nff.gz" before a ".gz" some format might have
    for (const SceneFormat& format : kFormats)
        for (const std::string_view extension : format.extensions)
            if (name.size() > extension.size() && name.ends_with(extension) &&
                extension.size() > longest) {
                found = &format;
                longest = extension.size();
            }
    return found;
}

std::string scene_formats_text() {
    std::string text;
    for (const SceneFormat& format : kFormats) {
        if (!text.empty()) text += ", ";
        for (std::size_t i = 0; i < format.extensions.size(); ++i)
            text += (i ? ", " : "") + std::string(format.extensions[i]);
        text += " (" + std::string(format.description) + ")";
    }
    return text;
}

}  // namespace glint
