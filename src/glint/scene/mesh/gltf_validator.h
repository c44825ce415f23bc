// Checks of the glTF JSON that Assimp 5.2 mishandles, made before it reads the file. Not a
// JSON parser: a scan for the keys concerned as they are written (a key spelled with \u escapes
// is not seen).
#pragma once

#include <filesystem>
#include <string_view>

namespace glint {

// `bytes` is the whole file, .gltf text or a .glb container (whose JSON is text inside it). An
// image's "mimeType" must hold a '/': Assimp takes what follows the '/' for a file extension
// and reads from address 1 when there is none. A buffer's or image's base64 data URI must hold
// base64 only: Assimp loses the memory it decoded into at a byte of 128 or more. A primitive's
// indices must be an accessor of SCALAR unsigned integers: Assimp leaks on any other. Throws
// SceneError at file:line:col for a .gltf file, naming the .glb file alone (binary, without lines)
// otherwise.
void validate_gltf_json(const std::filesystem::path& file, std::string_view bytes, bool binary);

}  // namespace glint
