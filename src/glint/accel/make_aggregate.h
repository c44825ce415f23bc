// Chooses an acceleration structure by kind or by name: the brute-force list (the reference)
// and the BVH (the default).
#pragma once

#include <memory>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include "glint/accel/aggregate.h"

namespace glint {

enum class AccelKind { list, bvh };

std::unique_ptr<Aggregate> make_aggregate(AccelKind kind, std::span<const Primitive> primitives);

std::string_view accel_name(AccelKind kind);
// Nothing for a name that is no structure's.
std::optional<AccelKind> accel_from_name(std::string_view name);
// The names of the structures this build has, in a stable order.
std::vector<std::string_view> accel_names();

}  // namespace glint
