// A light check of Wavefront OBJ files (and the MTL files they name) before Assimp reads them,
// so that a bad line is reported at file:line:col instead of as Assimp's unlocated message.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "glint/scene/read_sandbox.h"

namespace glint {

// Scans v, vt, vn, f, l and p lines (as Assimp does: every line that starts with f, l or p) and
// mtllib/usemtl, and the MTL files' colour, number and map_Kd lines. Throws SceneError at the
// first bad one: a non-numeric or non-finite coordinate, a face with fewer than 3 vertices, an
// index of a face, polyline or points that is 0 or out of range (positive indices against
// the file's total, negative ones against the elements before the face, as Assimp resolves
// them), a missing MTL file, a missing texture, an MTL file or texture outside the sandbox.
// Returns what the loader needs besides: warnings
// (e.g. usemtl of an unknown material), the MTL files and the undefined material names. Everything
// else (groups, smoothing groups) passes unchecked.
struct ObjCheck {
    std::vector<std::string> warnings;
    std::vector<std::filesystem::path> material_libraries;  // the MTL files, as found
    std::vector<std::string> undefined_materials;           // usemtl names that no MTL defines
};
ObjCheck validate_obj(const std::filesystem::path& file, std::string_view text,
                      const ReadSandbox& sandbox);

// The same for an MTL file on its own; `text` is its contents. Also throws for a statement before
// the first newmtl. Returns the material names it defines.
std::vector<std::string> validate_mtl(const std::filesystem::path& file, std::string_view text,
                                      const ReadSandbox& sandbox);

}  // namespace glint
