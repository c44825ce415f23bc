// Chooses an acceleration structure by kind or by name: the brute-force list (the reference),
// the BVH (the default), the uniform grid and the kd-tree.
#pragma once

#include <memory>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include "glint/accel/aggregate.h"

namespace glint {

enum class AccelKind {
    list,
    bvh,
    grid,    // uniform grid with a 3D-DDA (see grid_aggregate.h)
    kdtree,  // SAH kd-tree (see kdtree_aggregate.h)
#ifdef GLINT_HAVE_EMBREE
    embree,  // Intel Embree 3 (optional; see embree_aggregate.h)
#endif
};

std::unique_ptr<Aggregate> make_aggregate(AccelKind kind, std::span<const Primitive> primitives);

std::string_view accel_name(AccelKind kind);
// Nothing for a name that is no structure's.
std::optional<AccelKind> accel_from_name(std::string_view name);
// The names of the structures this build has, in a stable order.
std::vector<std::string_view> accel_names();

}  // namespace glint
