// The light buffer (Haines and Greenberg 1986): a direction cube around a point light whose
// cells list the primitives that can block a shadow feeler leaving the light in that cell's
// directions. A feeler then tests only its cell's list instead of the whole scene.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "glint/accel/primitive.h"
#include "glint/math/interval.h"
#include "glint/math/ray.h"

namespace glint {

class LightBuffer {
public:
    // Over the primitives visible to shadow rays; `resolution` cells along each edge of each of
    // the cube's six faces (0: chosen from the number of primitives). The primitives must
    // outlive the buffer.
    LightBuffer(Point3 light, std::span<const Primitive> primitives, int resolution = 0);

    Point3 light() const { return light_; }
    int resolution() const { return resolution_; }

    // Whether a primitive visible to shadow rays blocks the feeler `ray` (from a surface point
    // towards the light) within t_range; nothing when the feeler's cell lists more than
    // kMaxListTested primitives, where the acceleration structure answers faster. `hint` is a
    // primitive to test first (the last occluder of this light, kNoPrimitive for none); it is
    // set to the occluder found.
    std::optional<bool> occluded(const Ray& ray, Interval t_range, std::uint32_t& hint) const;

    // Longer cell lists are left to the acceleration structure: a list is tested one by one.
    static constexpr std::size_t kMaxListTested = 24;

    // Whether the buffer lists the shape and tests it whole. A mesh of more triangles than
    // kMaxListTested is a crowd of its own: the cells it covers are left to the acceleration
    // structure, which holds its triangles one by one.
    static bool tests_whole(const Shape& shape);

    // The primitives listed in the cell of a direction from the light (for tests).
    std::span<const std::uint32_t> candidates(Vector3 from_light) const;

    std::size_t memory_bytes() const;

    static constexpr std::uint32_t kNoPrimitive = 0xffffffffu;

private:
    std::uint32_t cell_of(Vector3 from_light) const;

    Point3 light_;
    int resolution_;
    std::span<const Primitive> primitives_;
    std::vector<std::uint32_t> cell_start_;  // 6 R^2 + 1 offsets into entries_
    std::vector<std::uint32_t> entries_;     // primitive indices, cell by cell
    std::vector<bool> crowded_;              // cells covered by a mesh not tested whole
    std::vector<std::uint32_t> unbounded_;   // planes: they may block any direction
};

}  // namespace glint
