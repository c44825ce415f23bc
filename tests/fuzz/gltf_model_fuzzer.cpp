// libFuzzer target: glTF 2.0 files. An input that starts with "glTF" is a binary model.glb;
// any other is JSON text up to the first NUL (model.gltf) and the buffer its seeds name
// (`"uri": "model.bin"`) after it.
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <span>

#include "fuzz_files.h"
#include "glint/scene/load_scene.h"
#include "glint/scene/scene_error.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::span<const std::uint8_t> bytes(data, size);
    try {
        if (size >= 4 && std::memcmp(data, "glTF", 4) == 0) {
            glint::load_scene(glint::fuzz::write_fuzz_file("model.glb", bytes));
        } else {
            const auto [json, buffer] = glint::fuzz::split_at_nul(bytes);
            glint::fuzz::write_fuzz_file("model.bin", buffer);  // always: none of an earlier input
            glint::load_scene(glint::fuzz::write_fuzz_file("model.gltf", json));
        }
    } catch (const glint::SceneError&) {
        // The loader's documented answer to bad input; anything else escapes and is a finding.
    }
    return 0;
}
