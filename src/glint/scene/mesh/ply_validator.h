// A check of PLY files before Assimp reads them: the header's element counts against the data
// that follows, so that a lying or absurd count is an error at its header line rather than a
// silently wrong mesh or a huge allocation.
#pragma once

#include <filesystem>
#include <string_view>

namespace glint {

// `bytes` is the whole file. Parses the header (format, elements, properties); then for ASCII
// files walks every data token (each must be a finite number, list lengths included) and checks
// face indices against the vertex count; for binary files checks that the data is at least as
// long as the counts need before walking it the same way. Throws SceneError at file:line:col
// (the header line of the element concerned for binary data), also for a file that does not
// start with the line "ply".
void validate_ply(const std::filesystem::path& file, std::string_view bytes);

}  // namespace glint
