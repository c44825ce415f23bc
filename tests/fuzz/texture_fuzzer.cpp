// libFuzzer target: texture images (PNG, JPEG, Radiance HDR, TGA, BMP) decoded from memory by
// stb_image through glint's bounds-checked reader.
#include <cstddef>
#include <cstdint>
#include <span>

#include "glint/image/image_error.h"
#include "glint/image/texture_file.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    try {
        glint::decode_texture_image(std::span(data, size), "texture");
    } catch (const glint::ImageError&) {
        // The loader's documented answer to bad input; anything else escapes and is a finding.
    }
    return 0;
}
