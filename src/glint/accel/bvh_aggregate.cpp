// Building the scene-level BVH over references, and its two queries.
#include "glint/accel/bvh_aggregate.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cassert>
#include <functional>
#include <stdexcept>

#include "glint/accel/rounding_margin.h"
#include "glint/accel/wide_bvh_packet.h"
#include "glint/geometry/made_on_first_use.h"
#include "glint/math/huge_page_allocator.h"

namespace glint {

namespace {

// Leaf kinds of the build: leaves of triangles or of spheres become blocks of four, anything else
// stays as it is.
constexpr std::uint8_t kWholeShape = 0;
constexpr std::uint8_t kTriangle = kBlockTriangle;
constexpr std::uint8_t kSphere = kBlockSphere;

// f(i) for every i in [0, n), on all threads: the per-triangle loops of a mesh of millions.
template <typename F>
void in_parallel(std::size_t n, F&& f) {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 4096),
                      [&](const tbb::blocked_range<std::size_t>& r) {
                          for (std::size_t i = r.begin(); i != r.end(); ++i) f(i);
                      });
}

const MeshData* mesh_of(const Primitive& p) {
    const auto* mesh = std::get_if<TriangleMesh>(&p.shape);
    return mesh ? mesh->data.get() : nullptr;
}

}  // namespace

BvhAggregate::BvhAggregate(std::span<const Primitive> primitives) : primitives_(primitives) {
    first_reference_.reserve(primitives.size() + 1);
    std::size_t total = 0;
    for (const Primitive& p : primitives) {
        first_reference_.push_back(std::uint32_t(total));
        const MeshData* mesh = mesh_of(p);
        const std::size_t references = mesh ? mesh->triangles.size() : 1;
        one_reference_each_ = one_reference_each_ && references == 1;
        total += references;
        if (total > kWideBvhMaxPrimitives)
            throw std::length_error("more than 2^29 shapes and triangles in one scene");
    }
    first_reference_.push_back(std::uint32_t(total));
    if (!primitives.empty()) {
        common_visibility_ = primitives.front().visibility;
        for (const Primitive& p : primitives)
            if (p.visibility != *common_visibility_) common_visibility_.reset();
    }

    // The bounded references, each with its box and kind; unbounded primitives go beside.
    LargeVector<std::uint32_t> bounded;  // build index -> reference
    LargeVector<Bounds3> boxes;
    LargeVector<std::uint8_t> kinds;
    bounded.reserve(total);
    boxes.reserve(total);
    kinds.reserve(total);
    for (std::uint32_t i = 0; i < primitives.size(); ++i) {
        const Primitive& p = primitives[i];
        if (const MeshData* mesh = mesh_of(p)) {
            const std::size_t at = bounded.size(), count = mesh->triangles.size();
            bounded.resize(at + count);
            boxes.resize(at + count);
            kinds.resize(at + count, kTriangle);
            in_parallel(count, [&](std::size_t t) {
                Bounds3 b;
                for (const std::uint32_t v : mesh->triangles[t]) b = merge(b, mesh->positions[v]);
                bounded[at + t] = first_reference_[i] + std::uint32_t(t);
                boxes[at + t] = b;
            });
            bounds_ = merge(bounds_, mesh->bounds);
            continue;
        }
        const Bounds3 b = glint::bounds(p.shape);
        if (!b.is_finite()) {
            unbounded_.push_back(i);
            continue;
        }
        bounded.push_back(first_reference_[i]);
        boxes.push_back(b);
        kinds.push_back(std::holds_alternative<Triangle>(p.shape) ? kTriangle
                        : std::holds_alternative<Sphere>(p.shape) ? kSphere
                                                                  : kWholeShape);
        bounds_ = merge(bounds_, b);
    }
    // Grown boxes: a hit on a box's face (a flat mesh, a shared edge) is never culled by the
    // rounding of the slab test, so ties at equal t resolve as in the list.
    const float margin = rounding_margin(bounds_);
    const Vector3 grow{margin, margin, margin};
    in_parallel(boxes.size(), [&](std::size_t k) {
        boxes[k] = {boxes[k].min - grow, boxes[k].max + grow};
    });
    // SAH counts triangles and spheres in blocks of four and other shapes one by one, as leaves
    // test them.
    bvh_ = build_wide_bvh(boxes, kWideBvhTriangleBuildOptions, kinds);
    // Triangle lanes name references; sphere lanes, and leaves of whole shapes, primitives. A kind
    // the scene has none of gets no function.
    const auto any = [&](std::uint8_t kind) {
        return std::find(kinds.begin(), kinds.end(), kind) != kinds.end();
    };
    std::function<BlockTriangle(std::uint32_t)> triangle_of;
    std::function<BlockSphere(std::uint32_t)> sphere_of;
    if (any(kTriangle))
        triangle_of = [&](std::uint32_t i) {
            const std::uint32_t ref = bounded[i];
            const Reference r = reference(ref);
            const Shape& shape = primitives[r.primitive].shape;
            if (const auto* triangle = std::get_if<Triangle>(&shape)) {
                const auto& v = triangle->vertices;
                return BlockTriangle{v[0], v[1], v[2], ref};
            }
            const MeshData& mesh = *std::get<TriangleMesh>(shape).data;
            const auto& t = mesh.triangles[r.triangle];
            return BlockTriangle{mesh.positions[t[0]], mesh.positions[t[1]], mesh.positions[t[2]],
                                 ref};
        };
    if (any(kSphere))
        sphere_of = [&](std::uint32_t i) {
            const std::uint32_t primitive = reference(bounded[i]).primitive;
            return BlockSphere{std::get<Sphere>(primitives[primitive].shape), primitive};
        };
    pack_block_leaves(bvh_, kinds, triangle_of, sphere_of);
    for (std::uint32_t& i : bvh_.primitive_indices) i = reference(bounded[i]).primitive;
}

BvhAggregate::Reference BvhAggregate::reference(std::uint32_t ref) const {
    if (one_reference_each_) return {ref, 0};
    const auto after = std::upper_bound(first_reference_.begin(), first_reference_.end(), ref);
    const auto primitive = std::uint32_t(after - first_reference_.begin() - 1);
    return {primitive, ref - first_reference_[primitive]};
}

// Plain values, not an std::optional, while the search runs: see BlockHit.
struct BvhAggregate::NearestHit {
    Hit closest{};
    bool found = false;

    // Keeps a hit nearer than the closest so far (or as near, and first in nearer()'s order) and
    // brings the range's far end to it.
    void consider(const Hit& candidate, Interval& range) {
        if (found && !nearer(candidate, closest)) return;
        closest = candidate;
        found = true;
        range.max = candidate.shape_hit.t;
    }
    std::optional<Hit> result() const { return found ? std::optional<Hit>(closest) : std::nullopt; }
};

inline GLINT_INLINE_LEAF void BvhAggregate::closest_in_unbounded(const Ray& ray,
                                                                 std::uint32_t ray_mask,
                                                                 NearestHit& nearest,
                                                                 Interval& range) const {
    for (const std::uint32_t i : unbounded_) {
        if (!visible(i, ray_mask)) continue;
        if (const auto hit = glint::intersect(primitives_[i].shape, ray, range))
            nearest.consider({*hit, i}, range);
    }
}

template <bool kSimd, class Triangles, class Spheres>
inline GLINT_INLINE_LEAF void BvhAggregate::closest_in_leaf(
    const Ray& ray, std::uint32_t leaf, std::uint32_t count, std::uint32_t ray_mask,
    Triangles&& triangles, Spheres&& spheres, NearestHit& nearest, Interval& range) const {
    switch (leaf_kind(leaf)) {
        case kWideTriangleLeaf:
            for (const TriangleBlock& block : leaf_blocks(bvh_, leaf, count)) {
                const BlockHit hit = triangles().template nearest<kSimd>(
                    block, range, triangle_lane_visible(block, ray_mask));
                if (!hit) continue;
                const Reference r = reference(block.id[hit.lane]);
                nearest.consider({{hit.t, hit.u, hit.v, r.triangle}, r.primitive}, range);
            }
            return;
        case kWideSphereLeaf:
            for (const SphereBlock& block : leaf_sphere_blocks(bvh_, leaf, count)) {
                const BlockHit hit = spheres().template nearest<kSimd>(
                    block, range, sphere_lane_visible(block, ray_mask));
                if (hit) nearest.consider({{hit.t}, block.id[hit.lane]}, range);
            }
            return;
        default:
            for (const std::uint32_t i : leaf_primitives(bvh_, leaf, count)) {
                if (!visible(i, ray_mask)) continue;
                if (const auto hit = glint::intersect(primitives_[i].shape, ray, range))
                    nearest.consider({*hit, i}, range);
            }
            return;
    }
}

std::optional<Hit> BvhAggregate::closest_hit(const Ray& ray, Interval t_range,
                                             std::uint32_t ray_mask) const {
    if (common_visibility_ && (*common_visibility_ & ray_mask) == 0) return std::nullopt;
    NearestHit nearest;
    closest_in_unbounded(ray, ray_mask, nearest, t_range);
    // Set up when a ray first reaches a leaf of their kind.
    MadeOnFirstUse<BlockTester, Ray> triangles(ray);
    MadeOnFirstUse<SphereTester, Ray> spheres(ray);
    bvh_closest_leaf(bvh_, ray, t_range,
                     [&](auto kernel, std::uint32_t leaf, std::uint32_t count, Interval& range)
                         GLINT_INLINE_LEAF {
                             closest_in_leaf<decltype(kernel)::kSimd>(
                                 ray, leaf, count, ray_mask,
                                 [&]() -> const BlockTester& { return triangles.get(); },
                                 [&]() -> const SphereTester& { return spheres.get(); }, nearest,
                                 range);
                         });
    return nearest.result();
}

void BvhAggregate::closest_hits(std::span<const Ray> rays, Interval t_range, std::uint32_t ray_mask,
                                std::optional<Hit>* hits) const {
    const std::size_t n = rays.size();
    assert(n <= std::size_t(kRayPacketSize));
    if (common_visibility_ && (*common_visibility_ & ray_mask) == 0) {
        std::fill_n(hits, n, std::nullopt);
        return;
    }
    std::array<NearestHit, kRayPacketSize> nearest;
    std::array<Interval, kRayPacketSize> ranges;
    for (std::size_t i = 0; i < n; ++i) {
        ranges[i] = t_range;
        closest_in_unbounded(rays[i], ray_mask, nearest[i], ranges[i]);
    }
    EachMadeOnFirstUse<BlockTester, Ray, kRayPacketSize> triangles(rays);
    EachMadeOnFirstUse<SphereTester, Ray, kRayPacketSize> spheres(rays);
    bvh_closest_leaf_packet(
        bvh_, rays, ranges.data(),
        [&](auto kernel, std::uint32_t leaf, std::uint32_t count, int lane, Interval& range)
            GLINT_INLINE_LEAF {
                const auto i = std::size_t(lane);
                closest_in_leaf<decltype(kernel)::kSimd>(
                    rays[i], leaf, count, ray_mask,
                    [&]() -> const BlockTester& { return triangles.get(i); },
                    [&]() -> const SphereTester& { return spheres.get(i); }, nearest[i], range);
            });
    for (std::size_t i = 0; i < n; ++i) hits[i] = nearest[i].result();
}

inline GLINT_INLINE_LEAF bool BvhAggregate::any_in_unbounded(const Ray& ray, Interval range,
                                                             std::uint32_t ray_mask) const {
    for (const std::uint32_t i : unbounded_)
        if (visible(i, ray_mask) && glint::intersect(primitives_[i].shape, ray, range)) return true;
    return false;
}

template <bool kSimd, class Triangles, class Spheres>
inline GLINT_INLINE_LEAF bool BvhAggregate::any_in_leaf(const Ray& ray, std::uint32_t leaf,
                                                        std::uint32_t count, std::uint32_t ray_mask,
                                                        Triangles&& triangles, Spheres&& spheres,
                                                        Interval range) const {
    switch (leaf_kind(leaf)) {
        case kWideTriangleLeaf:
            for (const TriangleBlock& block : leaf_blocks(bvh_, leaf, count))
                if (triangles().template any<kSimd>(block, range,
                                                    triangle_lane_visible(block, ray_mask)))
                    return true;
            return false;
        case kWideSphereLeaf:
            for (const SphereBlock& block : leaf_sphere_blocks(bvh_, leaf, count))
                if (spheres().template any<kSimd>(block, range,
                                                  sphere_lane_visible(block, ray_mask)))
                    return true;
            return false;
        default:
            for (const std::uint32_t i : leaf_primitives(bvh_, leaf, count))
                if (visible(i, ray_mask) && glint::intersect(primitives_[i].shape, ray, range))
                    return true;
            return false;
    }
}

bool BvhAggregate::any_hit(const Ray& ray, Interval t_range, std::uint32_t ray_mask) const {
    if (common_visibility_ && (*common_visibility_ & ray_mask) == 0) return false;
    if (any_in_unbounded(ray, t_range, ray_mask)) return true;
    MadeOnFirstUse<BlockTester, Ray> triangles(ray);
    MadeOnFirstUse<SphereTester, Ray> spheres(ray);
    return bvh_any_leaf(bvh_, ray, t_range,
                        [&](auto kernel, std::uint32_t leaf, std::uint32_t count, Interval range)
                            GLINT_INLINE_LEAF {
                                return any_in_leaf<decltype(kernel)::kSimd>(
                                    ray, leaf, count, ray_mask,
                                    [&]() -> const BlockTester& { return triangles.get(); },
                                    [&]() -> const SphereTester& { return spheres.get(); }, range);
                            });
}

unsigned BvhAggregate::any_hits(std::span<const Ray> rays, const Interval* t_ranges,
                                std::uint32_t ray_mask) const {
    const std::size_t n = rays.size();
    assert(n <= std::size_t(kRayPacketSize));
    if (common_visibility_ && (*common_visibility_ & ray_mask) == 0) return 0;
    // Rays a plane blocks are done; the others go through the tree together.
    PacketSubset left;
    unsigned blocked = 0;
    for (std::size_t i = 0; i < n; ++i) {
        if (any_in_unbounded(rays[i], t_ranges[i], ray_mask))
            blocked |= 1u << i;
        else
            left.add(i, rays[i], t_ranges[i]);
    }
    if (left.size == 0) return blocked;
    EachMadeOnFirstUse<BlockTester, Ray, kRayPacketSize> triangles(left.rays_span());
    EachMadeOnFirstUse<SphereTester, Ray, kRayPacketSize> spheres(left.rays_span());
    const unsigned found = bvh_any_leaf_packet(
        bvh_, left.rays_span(), left.ranges.data(),
        [&](auto kernel, std::uint32_t leaf, std::uint32_t count, int lane, Interval range)
            GLINT_INLINE_LEAF {
                const auto i = std::size_t(lane);
                return any_in_leaf<decltype(kernel)::kSimd>(
                    left.rays[i], leaf, count, ray_mask,
                    [&]() -> const BlockTester& { return triangles.get(i); },
                    [&]() -> const SphereTester& { return spheres.get(i); }, range);
            });
    return blocked | left.in_packet(found);
}

std::size_t BvhAggregate::memory_bytes() const {
    return sizeof(*this) + bvh_.memory_bytes() +
           first_reference_.capacity() * sizeof(std::uint32_t) +
           unbounded_.capacity() * sizeof(std::uint32_t);
}

AccelStats BvhAggregate::statistics() const {
    AccelStatsTally tally(bvh_.root_bounds);
    // Lanes in use: a block's unused lanes have no id.
    const auto leaf_references = [&](std::uint32_t leaf, std::uint32_t count) {
        std::size_t n = 0;
        switch (leaf_kind(leaf)) {
            case kWideTriangleLeaf:
                for (const TriangleBlock& block : leaf_blocks(bvh_, leaf, count))
                    for (const std::uint32_t id : block.id) n += id != kNoTriangle;
                return n;
            case kWideSphereLeaf:
                for (const SphereBlock& block : leaf_sphere_blocks(bvh_, leaf, count))
                    for (const std::uint32_t id : block.id) n += id != kNoSphere;
                return n;
            default:
                return std::size_t(count);
        }
    };
    // Depth first; the depth is bounded by the binary tree's (kBvhMaxDepth).
    const auto walk = [&](const auto& self, std::uint32_t index, int depth) -> void {
        const WideBvhNode& node = bvh_.nodes[index];
        for (int slot = 0; slot < kWideBvhWidth; ++slot) {
            if (!node.is_leaf(slot)) {
                tally.interior(node.child_bounds(slot));
                self(self, node.child[slot], depth + 1);
            } else if (node.count[slot] > 0) {
                tally.leaf(node.child_bounds(slot), depth + 1,
                           leaf_references(node.child[slot], node.count[slot]));
            }
        }
    };
    if (!bvh_.nodes.empty()) {
        tally.interior(bvh_.root_bounds);
        walk(walk, 0, 0);
    }
    return tally.finish(unbounded_.size(), memory_bytes());
}

}  // namespace glint
