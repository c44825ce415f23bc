// The GLB container's header and chunk lengths, walked as Assimp walks them.
#include "glint/scene/mesh/glb_validator.h"

#include <cstdint>
#include <string>

#include "glint/scene/scene_error.h"

namespace glint {

namespace {

std::uint32_t little_endian32(std::string_view bytes, std::size_t at) {
    const auto byte = [&](std::size_t i) { return std::uint32_t(std::uint8_t(bytes[at + i])); };
    return byte(0) | byte(1) << 8 | byte(2) << 16 | byte(3) << 24;
}

}  // namespace

void validate_glb(const std::filesystem::path& file, std::string_view bytes) {
    const auto error = [&](const std::string& message) {
        return SceneError({file.string(), 0, 0}, message);
    };
    if (bytes.size() < 12 || bytes.substr(0, 4) != "glTF") {
        throw error("not a binary glTF file: it does not start with a 12-byte header \"glTF\"");
    }
    const std::uint32_t version = little_endian32(bytes, 4);
    if (version != 2) {
        throw error("GLB version " + std::to_string(version) + "; glint reads version 2");
    }
    const std::uint32_t length = little_endian32(bytes, 8);
    if (length > bytes.size()) {
        throw error("the GLB header gives a length of " + std::to_string(length) +
                    " bytes, but the file has " + std::to_string(bytes.size()) +
                    " (it is truncated)");
    }
    // Assimp reads the JSON chunk's header whatever length the header gives.
    if (length < 20) {
        throw error("the GLB header gives a length of " + std::to_string(length) +
                    " bytes, too short for the 12-byte header and a chunk (at least 20)");
    }
    std::uint64_t at = 12;
    while (at + 8 <= length) {
        const std::uint64_t chunk = little_endian32(bytes, at);
        if (at + 8 + chunk > length) {
            throw error("the GLB chunk at byte " + std::to_string(at) + " claims " +
                        std::to_string(chunk) + " bytes, past the end of the file's " +
                        std::to_string(length));
        }
        at += 8 + chunk;
    }
}

}  // namespace glint
