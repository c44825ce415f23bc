// Checks of the glTF JSON that Assimp 5.2 mishandles, made before it reads the file. Not a
// JSON parser: a scan for the keys concerned as they are written (a key spelled with \u escapes
// is not seen).
#pragma once

#include <filesystem>
#include <string_view>

namespace glint {

// `bytes` is the whole file, .gltf text or a .glb container (whose JSON is text inside it). An
// image's "mimeType" must hold a '/': Assimp takes what follows the '/' for a file extension
// and reads from address 1 when there is none. Throws SceneError at file:line:col for a .gltf
// file, naming the .glb file alone (binary, without lines) otherwise.
void validate_gltf_json(const std::filesystem::path& file, std::string_view bytes, bool binary);

}  // namespace glint
