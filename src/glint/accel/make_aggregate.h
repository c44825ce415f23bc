// Chooses an acceleration structure: the brute-force list (the reference) or the BVH (the
// default); the grid and the kd-tree will join them.
#pragma once

#include <memory>
#include <span>

#include "glint/accel/aggregate.h"

namespace glint {

enum class AccelKind { list, bvh };

std::unique_ptr<Aggregate> make_aggregate(AccelKind kind, std::span<const Primitive> primitives);

}  // namespace glint
