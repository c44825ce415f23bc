// NFF's view entity (`v` and its lines from, at, up, angle, hither, resolution), read and checked.
#pragma once

#include <array>
#include <cstdint>
#include <string_view>

#include "glint/scene/nff/nff_scene.h"
#include "glint/scene/nff/nff_tokenizer.h"

namespace glint {

// The view's lines, in the order they must come.
inline constexpr std::array<std::string_view, 6> kNffViewLines = {"from",  "at",     "up",
                                                                  "angle", "hither", "resolution"};
// A note for errors about the view.
inline constexpr const char* kNffViewOrder =
    "a view is a \"v\" line followed by six lines in this order: from x y z, at x y z, "
    "up x y z, angle degrees, hither distance, resolution width height";

// Reads the six lines after the `v` keyword. Checks the angle (in (0, 180)), the resolution
// (sides within glint's ceiling, at most max_pixels in all), that at differs from from, and that
// up is not along the view. Throws SceneError at the offending token.
NffView read_nff_view(NffTokenizer& tokens, const NffToken& keyword, std::int64_t max_pixels);

}  // namespace glint
