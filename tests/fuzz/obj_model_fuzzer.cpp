// libFuzzer target: OBJ files with their MTL file. The input's bytes up to the first NUL are
// model.obj, those after it model.mtl (which seeds name with `mtllib model.mtl`).
#include <cstddef>
#include <cstdint>
#include <span>

#include "fuzz_files.h"
#include "glint/scene/load_scene.h"
#include "glint/scene/scene_error.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const auto [obj, mtl] = glint::fuzz::split_at_nul(std::span(data, size));
    try {
        glint::fuzz::write_fuzz_file("model.mtl", mtl);  // always: no MTL of an earlier input
        glint::load_scene(glint::fuzz::write_fuzz_file("model.obj", obj));
    } catch (const glint::SceneError&) {
        // The loader's documented answer to bad input; anything else escapes and is a finding.
    }
    return 0;
}
