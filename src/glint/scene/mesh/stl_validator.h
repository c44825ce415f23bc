// A line-by-line check of ASCII STL files before Assimp reads them, so that a bad line is
// reported at file:line:col instead of as Assimp's unlocated message.
#pragma once

#include <filesystem>
#include <string_view>

namespace glint {

// `bytes` is the whole file. Files Assimp reads as binary STL (84 + 50 n bytes, n the count in
// bytes 80-83), and files that do not start with "solid", are left to Assimp. Otherwise every
// line is checked against the grammar
//   solid [name]
//     facet normal nx ny nz
//       outer loop
//         vertex x y z        (three of them: STL facets are triangles)
//       endloop
//     endfacet
//   endsolid [name]
// (several solids may follow one another; blank lines anywhere), with finite numbers. Throws
// SceneError at the first bad token. A file that ends after a complete facet without `endsolid`
// passes, as Assimp reads it; one that ends inside a facet does not.
void validate_stl(const std::filesystem::path& file, std::string_view bytes);

}  // namespace glint
