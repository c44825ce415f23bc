// A check of binary glTF (.glb) containers before Assimp reads them: the header's length and
// every chunk's against the file's size, since Assimp allocates a chunk's claimed length first.
#pragma once

#include <filesystem>
#include <string_view>

namespace glint {

// `bytes` is the whole file. Checks the 12-byte header (magic "glTF", version 2, a total length
// within the file) and that every chunk (an 8-byte header and its data) ends within that
// length. Throws SceneError naming the file (GLB has no lines), the byte offset in the message.
// The JSON inside is left to Assimp.
void validate_glb(const std::filesystem::path& file, std::string_view bytes);

}  // namespace glint
