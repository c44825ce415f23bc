// libFuzzer target: STL files (ASCII and binary), loaded as a whole scene through glint's validator
// and Assimp.
#include <cstddef>
#include <cstdint>
#include <span>

#include "fuzz_files.h"
#include "glint/scene/load_scene.h"
#include "glint/scene/scene_error.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    try {
        glint::load_scene(glint::fuzz::write_fuzz_file("model.stl", std::span(data, size)));
    } catch (const glint::SceneError&) {
        // The loader's documented answer to bad input; anything else escapes and is a finding.
    }
    return 0;
}
