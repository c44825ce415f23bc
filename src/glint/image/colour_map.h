// Colours for pictures of numbers (the output variables' PNGs): a perceptual map for a value in a
// range, and distinct colours for ids.
#pragma once

#include <cstdint>

#include "glint/math/color.h"

namespace glint {

// Viridis (van der Walt and Smith, matplotlib), dark blue at 0 to yellow at 1, as linear colour:
// even steps in lightness, readable in grey and by colour-blind eyes. t is clamped to [0, 1].
Color colour_map(float t);

// A colour of its own for each id, well apart from its neighbours' (hues a golden angle apart,
// in three lightnesses); black for a negative id (nothing).
Color id_colour(std::int32_t id);

}  // namespace glint
