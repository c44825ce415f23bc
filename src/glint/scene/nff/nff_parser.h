// Reads NFF, the Neutral File Format of Eric Haines' Standard Procedural Databases, into an
// NffScene (plain data; turning it into a glint Scene is a separate step).
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

#include "glint/image/image_limits.h"  // kMaxImagePixels
#include "glint/scene/nff/nff_scene.h"
#include "glint/scene/scene_error.h"

namespace glint {

// Larger files, or gzipped files that inflate to more, are refused before they fill memory. The
// SPD's largest file is 92 MB; the next size factors up would be 190 to 370 MB.
inline constexpr std::uint64_t kMaxNffFileBytes = std::uint64_t(1) << 30;
// Pieces of text that parse_nff reads in parallel.
inline constexpr std::size_t kNffPieceBytes = std::size_t(1) << 22;
// A polygon of more vertices is refused before memory is taken for them.
inline constexpr std::int64_t kMaxNffPolygonVertices = 1'000'000;

// Parses NFF text; file_name is used in error locations. Entities may come in any order (the SPD
// writes `b` before `v`), numbers anywhere on their entity's lines or the lines after (the SPD
// writes a cone's 8 numbers on its `c` line, the spec on two lines after it). Every value is
// checked: a malformed file gives a SceneError at the offending token. A file without a view
// parses; require_view() says what is missing. Throws SceneError only.
// Text longer than piece_bytes is read in pieces of about that size in parallel, with the same
// result, errors included (a file with an error is read again in one piece to report it). A view
// of more than max_pixels is an error at its resolution (SceneLimits::image_pixels).
NffScene parse_nff(std::string_view text, const std::string& file_name,
                   std::size_t piece_bytes = kNffPieceBytes,
                   std::int64_t max_pixels = kMaxImagePixels);

// Reads a .nff file, or a gzip-compressed one (.nff.gz, recognised by its content), of at most
// max_bytes once decompressed, and parses it. Throws SceneError only.
NffScene load_nff(const std::filesystem::path& file, std::uint64_t max_bytes = kMaxNffFileBytes,
                  std::int64_t max_pixels = kMaxImagePixels);

// The view, or a SceneError saying that the file has none.
const NffView& require_view(const NffScene& scene);

}  // namespace glint
