// libFuzzer target: the image readers of glint's output formats (PPM, PFM, PNG, EXR), which
// read by path: the input's first bytes pick the extension it is written under.
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <span>
#include <string_view>

#include "fuzz_files.h"
#include "glint/image/image_error.h"
#include "glint/image/image_io.h"

namespace {

bool starts_with(std::span<const std::uint8_t> bytes, std::string_view magic) {
    return bytes.size() >= magic.size() &&
           std::memcmp(bytes.data(), magic.data(), magic.size()) == 0;
}

// By the format's magic number; PPM for anything else, whose reader then refuses the magic.
std::string_view file_name_for(std::span<const std::uint8_t> bytes) {
    if (starts_with(bytes, "PF") || starts_with(bytes, "Pf")) return "image.pfm";
    if (starts_with(bytes, "\x89PNG")) return "image.png";
    if (starts_with(bytes, "\x76\x2f\x31\x01")) return "image.exr";
    return "image.ppm";
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::span<const std::uint8_t> bytes(data, size);
    try {
        glint::read_image(glint::fuzz::write_fuzz_file(file_name_for(bytes), bytes));
    } catch (const glint::ImageError&) {
        // The reader's documented answer to bad input; anything else escapes and is a finding.
    }
    return 0;
}
