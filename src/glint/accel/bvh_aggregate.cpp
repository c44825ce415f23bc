// Building the scene-level BVH over references, and its two queries.
#include "glint/accel/bvh_aggregate.h"

#include <algorithm>
#include <stdexcept>

#include "glint/accel/rounding_margin.h"

namespace glint {

namespace {

// Leaf kinds of the build: a leaf of triangles becomes blocks, anything else stays as it is.
constexpr std::uint8_t kWholeShape = 0;
constexpr std::uint8_t kTriangle = 1;

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
        total += mesh ? mesh->triangles.size() : 1;
        if (total >= kWideBlockLeaf)
            throw std::length_error("more than 2^30 shapes and triangles in one scene");
    }
    first_reference_.push_back(std::uint32_t(total));
    if (!primitives.empty()) {
        common_visibility_ = primitives.front().visibility;
        for (const Primitive& p : primitives)
            if (p.visibility != *common_visibility_) common_visibility_.reset();
    }

    // The bounded references, each with its box and kind; unbounded primitives go beside.
    std::vector<std::uint32_t> bounded;  // build index -> reference
    std::vector<Bounds3> boxes;
    std::vector<std::uint8_t> kinds;
    for (std::uint32_t i = 0; i < primitives.size(); ++i) {
        const Primitive& p = primitives[i];
        if (const MeshData* mesh = mesh_of(p)) {
            for (std::uint32_t t = 0; t < mesh->triangles.size(); ++t) {
                Bounds3 b;
                for (const std::uint32_t v : mesh->triangles[t]) b = merge(b, mesh->positions[v]);
                bounded.push_back(first_reference_[i] + t);
                boxes.push_back(b);
                kinds.push_back(kTriangle);
            }
            bounds_ = merge(bounds_, mesh->bounds);
            continue;
        }
        const Bounds3 b = glint::bounds(p.shape);
        if (!b.is_finite()) {
            unbounded_.push_back(i);
            continue;
        }
        const bool triangle = std::holds_alternative<Triangle>(p.shape);
        bounded.push_back(first_reference_[i]);
        boxes.push_back(b);
        kinds.push_back(triangle ? kTriangle : kWholeShape);
        bounds_ = merge(bounds_, b);
    }
    // Grown boxes: a hit on a box's face (a flat mesh, a shared edge) is never culled by the
    // rounding of the slab test, so ties at equal t resolve as in the list.
    const float margin = rounding_margin(bounds_);
    const Vector3 grow{margin, margin, margin};
    for (Bounds3& b : boxes) b = {b.min - grow, b.max + grow};
    // SAH counts triangles in blocks of four and other shapes one by one, as leaves test them.
    bvh_ = build_wide_bvh(boxes, kWideBvhTriangleBuildOptions, kinds);
    pack_triangle_leaves(bvh_, [&](std::uint32_t i) -> std::optional<BlockTriangle> {
        if (kinds[i] != kTriangle) return std::nullopt;
        const std::uint32_t ref = bounded[i];
        const Reference r = reference(ref);
        const Shape& shape = primitives[r.primitive].shape;
        if (const auto* triangle = std::get_if<Triangle>(&shape)) {
            const auto& v = triangle->vertices;
            return BlockTriangle{v[0], v[1], v[2], ref};
        }
        const MeshData& mesh = *std::get<TriangleMesh>(shape).data;
        const auto& t = mesh.triangles[r.triangle];
        return BlockTriangle{mesh.positions[t[0]], mesh.positions[t[1]], mesh.positions[t[2]], ref};
    });
    // The leaves of whole shapes name primitives: a reference of one is its primitive's first.
    for (std::uint32_t& i : bvh_.primitive_indices) i = reference(bounded[i]).primitive;
}

BvhAggregate::Reference BvhAggregate::reference(std::uint32_t ref) const {
    const auto after = std::upper_bound(first_reference_.begin(), first_reference_.end(), ref);
    const auto primitive = std::uint32_t(after - first_reference_.begin() - 1);
    return {primitive, ref - first_reference_[primitive]};
}

std::optional<Hit> BvhAggregate::closest_hit(const Ray& ray, Interval t_range,
                                             std::uint32_t ray_mask) const {
    if (common_visibility_ && (*common_visibility_ & ray_mask) == 0) return std::nullopt;
    std::optional<Hit> closest;
    const auto consider = [&](const Hit& candidate) {
        if (closest && !nearer(candidate, *closest)) return false;
        closest = candidate;
        return true;
    };
    for (const std::uint32_t i : unbounded_) {
        if (!visible(i, ray_mask)) continue;
        const auto hit = glint::intersect(primitives_[i].shape, ray, t_range);
        if (hit && consider({*hit, i})) t_range.max = hit->t;
    }
    const BlockTester tester(ray);
    bvh_closest_leaf(bvh_, ray, t_range,
                     [&](auto kernel, std::uint32_t leaf, std::uint32_t count,
                         Interval range) GLINT_INLINE_LEAF -> std::optional<float> {
                         std::optional<float> found;
                         if ((leaf & kWideBlockLeaf) != 0) {
                             for (const TriangleBlock& block : leaf_blocks(bvh_, leaf, count)) {
                                 const auto lane_visible = [&](int lane) {
                                     return common_visibility_ ||
                                            visible(reference(block.id[lane]).primitive, ray_mask);
                                 };
                                 const auto hit = tester.nearest<decltype(kernel)::kSimd>(
                                     block, range, lane_visible);
                                 if (!hit) continue;
                                 const Reference r = reference(block.id[hit->lane]);
                                 if (consider({{hit->t, hit->u, hit->v, r.triangle}, r.primitive}))
                                     range.max = *(found = hit->t);
                             }
                             return found;
                         }
                         for (const std::uint32_t i : leaf_primitives(bvh_, leaf, count)) {
                             if (!visible(i, ray_mask)) continue;
                             const auto hit = glint::intersect(primitives_[i].shape, ray, range);
                             if (hit && consider({*hit, i})) range.max = *(found = hit->t);
                         }
                         return found;
                     });
    return closest;
}

bool BvhAggregate::any_hit(const Ray& ray, Interval t_range, std::uint32_t ray_mask) const {
    if (common_visibility_ && (*common_visibility_ & ray_mask) == 0) return false;
    for (const std::uint32_t i : unbounded_) {
        if (visible(i, ray_mask) && glint::intersect(primitives_[i].shape, ray, t_range))
            return true;
    }
    const BlockTester tester(ray);
    return bvh_any_leaf(
        bvh_, ray, t_range,
        [&](auto kernel, std::uint32_t leaf, std::uint32_t count, Interval range)
            GLINT_INLINE_LEAF {
                if ((leaf & kWideBlockLeaf) != 0) {
                    for (const TriangleBlock& block : leaf_blocks(bvh_, leaf, count)) {
                        const auto lane_visible = [&](int lane) {
                            return common_visibility_ ||
                                   visible(reference(block.id[lane]).primitive, ray_mask);
                        };
                        if (tester.any<decltype(kernel)::kSimd>(block, range, lane_visible))
                            return true;
                    }
                    return false;
                }
                for (const std::uint32_t i : leaf_primitives(bvh_, leaf, count)) {
                    if (visible(i, ray_mask) && glint::intersect(primitives_[i].shape, ray, range))
                        return true;
                }
                return false;
            });
}

std::size_t BvhAggregate::memory_bytes() const {
    return sizeof(*this) + bvh_.memory_bytes() +
           first_reference_.capacity() * sizeof(std::uint32_t) +
           unbounded_.capacity() * sizeof(std::uint32_t);
}

}  // namespace glint
