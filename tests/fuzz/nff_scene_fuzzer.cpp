// libFuzzer target: NFF scene files, plain or gzip-compressed (recognised by content), read as
// `glint render x.nff` reads them; plain text is also parsed in small pieces in parallel, which
// must give the same answer as one piece.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "fuzz_files.h"
#include "glint/scene/nff/nff_parser.h"
#include "glint/scene/nff/nff_to_scene.h"
#include "glint/scene/scene_error.h"

namespace {

// Inflating gigabyte bombs proves nothing new each time and slows the fuzzer to a crawl; the
// limit itself is tested in tests/scene/gzip_file_test.cpp.
constexpr std::uint64_t kFuzzMaxBytes = std::uint64_t(16) << 20;

// The parse's error message, or nothing when it succeeds.
std::optional<std::string> parse_error(std::string_view text, std::size_t piece_bytes) {
    try {
        glint::parse_nff(text, "scene.nff", piece_bytes);
        return std::nullopt;
    } catch (const glint::SceneError& e) {
        return glint::format_scene_error(e);
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::span<const std::uint8_t> bytes(data, size);
    try {
        const auto file = glint::fuzz::write_fuzz_file("scene.nff", bytes);
        glint::nff_to_scene(glint::load_nff(file, kFuzzMaxBytes));
    } catch (const glint::SceneError&) {
        // The loader's documented answer to bad input; anything else escapes and is a finding.
    }
    const bool gzipped = size >= 2 && data[0] == 0x1f && data[1] == 0x8b;
    if (!gzipped) {
        const std::string_view text(reinterpret_cast<const char*>(data), size);
        if (parse_error(text, 64) != parse_error(text, glint::kNffPieceBytes)) std::abort();
    }
    return 0;
}
