// Russian roulette (Arvo and Kirk 1990) for the physically based integrators' paths and
// particles: after the third surface, one whose throughput has fallen below 1 goes on with that
// probability (at least 5%), and what it brings back then counts that much more, so that the
// expected value does not change and paths that carry little end early.
#pragma once

#include <algorithm>

#include "glint/math/color.h"

namespace glint {

inline constexpr int kRouletteDepth = 3;
inline constexpr float kLeastSurvival = 0.05f;

// The probability a path of this throughput at this depth (surfaces met, the first 1) goes on.
inline float survival_probability(Color throughput, int depth) {
    if (depth < kRouletteDepth) return 1;
    const float survival = std::min(1.0f, max_channel(throughput));
    return survival < 1 ? std::max(kLeastSurvival, survival) : 1;
}

}  // namespace glint
