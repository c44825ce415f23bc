// Bounds on mesh files, checked before any memory is taken for them (DESIGN principle 4).
#pragma once

#include <cstdint>

namespace glint {

// Larger mesh files (and MTL files) are refused before they are read.
inline constexpr std::uintmax_t kMaxMeshFileBytes = std::uintmax_t(2) << 30;

}  // namespace glint
