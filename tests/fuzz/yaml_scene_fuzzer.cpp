// libFuzzer target: glint's YAML scene format, parsed in memory as a file of the fuzz folder so
// that the meshes and textures it names by relative path are looked for there: a triangle in
// model.obj and a 2 x 2 texture.tga, which the seeds use.
#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>

#include "fuzz_files.h"
#include "glint/scene/scene_error.h"
#include "glint/scene/yaml/yaml_scene_loader.h"

namespace {

constexpr std::string_view kTriangle = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
// An uncompressed 24-bit TGA: the 18-byte header, then blue, green, red from the bottom row.
constexpr std::uint8_t kTexture[] = {0, 0,  2, 0, 0, 0,   0, 0,   0, 0,   0, 0, 2,   0,   2,
                                     0, 24, 0, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 255};

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
    glint::fuzz::write_fuzz_file("model.obj", kTriangle);
    glint::fuzz::write_fuzz_file("texture.tga", kTexture);
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    try {
        glint::parse_yaml_scene(text, (glint::fuzz::fuzz_folder() / "scene.yaml").string());
    } catch (const glint::SceneError&) {
        // The loader's documented answer to bad input; anything else escapes and is a finding.
    }
    return 0;
}
