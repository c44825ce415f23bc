// Filling sphere blocks.
#include "glint/geometry/sphere_block.h"

#include <limits>

namespace glint {

SphereBlock empty_sphere_block() {
    SphereBlock block;
    const float nan = std::numeric_limits<float>::quiet_NaN();
    for (auto& axis : block.center)
        for (float& x : axis) x = nan;
    for (float& r : block.radius) r = nan;
    for (std::uint32_t& id : block.id) id = kNoSphere;
    return block;
}

void set_sphere_lane(SphereBlock& block, int lane, const Sphere& sphere, std::uint32_t id) {
    block.center[0][lane] = sphere.center.x;
    block.center[1][lane] = sphere.center.y;
    block.center[2][lane] = sphere.center.z;
    block.radius[lane] = sphere.radius;
    block.id[lane] = id;
}

}  // namespace glint
