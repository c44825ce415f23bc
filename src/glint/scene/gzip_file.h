// Reading a whole scene file into memory, gunzipping it on the way when it is gzip-compressed,
// within a size limit that holds for the decompressed text too (so a gzip bomb is an error).
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>

#include "glint/scene/scene_error.h"

namespace glint {

// The file's text: its bytes, or, when they start with the gzip magic number (1f 8b), what they
// decompress to (every member of a multi-member file, as gunzip does). Refuses more than
// max_bytes of text, checked while streaming, before the memory is taken. Throws SceneError,
// located at the file without a line: cannot be read, a directory, too large, corrupt or
// truncated gzip data, or a name ending in .gz on a file that is not gzip-compressed.
std::string read_maybe_gzipped(const std::filesystem::path& file, std::uint64_t max_bytes);

}  // namespace glint
