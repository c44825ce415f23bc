// libFuzzer target: POV-Ray scene files, read as `glint render x.pov` reads them, from a file of
// the fuzz folder, so that `#include "shapes.inc"` finds the small include file written there.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "fuzz_files.h"
#include "glint/scene/pov/pov_scene.h"
#include "glint/scene/scene_error.h"

namespace {

constexpr std::string_view kInclude =
    "#declare Size = 2;\n#macro Twice(V) (2 * V) #end\n#declare Ball = sphere { 0, Size }\n";

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
    glint::fuzz::write_fuzz_file("shapes.inc", kInclude);
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    const auto file = glint::fuzz::fuzz_folder() / "scene.pov";
    try {
        glint::ReadSandbox sandbox = glint::make_read_sandbox(file);
        // Endless loops are found at once, and the corpus's looping scripts run in half the time
        // they took at 10,000 (under ASan); the limit itself is tested in pov_language_test.
        sandbox.limits.script_loop_iterations = 1000;
        glint::parse_pov_scene(std::string(text), file, sandbox);
    } catch (const glint::SceneError&) {
        // The loader's documented answer to bad input; anything else escapes and is a finding.
    }
    return 0;
}
