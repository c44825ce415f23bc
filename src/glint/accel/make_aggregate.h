// Chooses an acceleration structure by name. Only the brute-force list exists yet; the BVH,
// grid and kd-tree join this table.
#pragma once

#include <memory>
#include <span>

#include "glint/accel/aggregate.h"

namespace glint {

enum class AccelKind { list };

std::unique_ptr<Aggregate> make_aggregate(AccelKind kind, std::span<const Primitive> primitives);

}  // namespace glint
