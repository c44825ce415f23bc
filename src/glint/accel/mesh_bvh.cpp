// Building each traced-whole mesh's BVH and binding it into the shapes that hold the mesh.
#include "glint/accel/mesh_bvh.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cassert>
#include <unordered_map>
#include <utility>
#include <vector>

#include "glint/accel/wide_bvh_packet.h"
#include "glint/geometry/made_on_first_use.h"

namespace glint {

static_assert(kMaxMeshElements <= kWideBvhMaxPrimitives, "a wide BVH indexes every triangle");

MeshBvh::MeshBvh(std::shared_ptr<const MeshData> mesh) : mesh_(std::move(mesh)) {
    const MeshData& m = *mesh_;
    std::vector<Bounds3> bounds(m.triangles.size());
    for (std::size_t i = 0; i < bounds.size(); ++i) {
        const auto& t = m.triangles[i];
        bounds[i] = merge(Bounds3::of(m.positions[t[0]], m.positions[t[1]]), m.positions[t[2]]);
    }
    bvh_ = build_wide_bvh(bounds, kWideBvhTriangleBuildOptions);
    pack_block_leaves(bvh_, {}, [&](std::uint32_t i) {
        const auto& t = m.triangles[i];
        return BlockTriangle{m.positions[t[0]], m.positions[t[1]], m.positions[t[2]], i};
    });
}

namespace {

// The nearest hit so far of one ray, and the leaf test that finds nearer ones.
struct NearestTriangle {
    ShapeHit hit;
    bool found = false;

    // The leaf's triangles against the ray: a nearer hit (at equal t the lower triangle, whatever
    // the order of the leaves) is kept and brings range.max to it.
    template <bool kSimd>
    [[gnu::always_inline]] inline void test(const BlockTester& tester,
                                            std::span<const TriangleBlock> blocks,
                                            Interval& range) {
        for (const TriangleBlock& block : blocks) {
            const BlockHit h = tester.nearest<kSimd>(block, range, kEveryLane);
            if (!h) continue;
            const std::uint32_t part = block.id[h.lane];
            if (found && h.t == hit.t && part > hit.part) continue;
            hit = ShapeHit{h.t, h.u, h.v, part};
            found = true;
            range.max = h.t;
        }
    }
};

template <bool kSimd>
[[gnu::always_inline]] inline bool blocks_occlude(const BlockTester& tester,
                                                  std::span<const TriangleBlock> blocks,
                                                  Interval range) {
    for (const TriangleBlock& block : blocks)
        if (tester.any<kSimd>(block, range, kEveryLane)) return true;
    return false;
}

// The block testers of a packet's rays.
using PacketTesters = EachMadeOnFirstUse<BlockTester, Ray, kRayPacketSize>;

}  // namespace

std::optional<ShapeHit> MeshBvh::intersect(const Ray& ray, Interval t_range) const {
    const BlockTester tester(ray);
    NearestTriangle nearest;
    bvh_closest_leaf(bvh_, ray, t_range,
                     [&](auto kernel, std::uint32_t leaf, std::uint32_t count, Interval& range)
                         GLINT_INLINE_LEAF {
                             nearest.test<decltype(kernel)::kSimd>(
                                 tester, leaf_blocks(bvh_, leaf, count), range);
                         });
    if (!nearest.found) return std::nullopt;
    return nearest.hit;
}

bool MeshBvh::occluded(const Ray& ray, Interval t_range) const {
    const BlockTester tester(ray);
    return bvh_any_leaf(bvh_, ray, t_range,
                        [&](auto kernel, std::uint32_t leaf, std::uint32_t count, Interval range)
                            GLINT_INLINE_LEAF {
                                return blocks_occlude<decltype(kernel)::kSimd>(
                                    tester, leaf_blocks(bvh_, leaf, count), range);
                            });
}

void MeshBvh::intersect_packet(std::span<const Ray> rays, const Interval* t_ranges,
                               std::optional<ShapeHit>* hits) const {
    assert(rays.size() <= std::size_t(kRayPacketSize));
    PacketTesters testers(rays);
    std::array<NearestTriangle, kRayPacketSize> nearest;
    std::array<Interval, kRayPacketSize> ranges;
    std::copy_n(t_ranges, rays.size(), ranges.begin());
    bvh_closest_leaf_packet(
        bvh_, rays, ranges.data(),
        [&](auto kernel, std::uint32_t leaf, std::uint32_t count, int lane, Interval& range)
            GLINT_INLINE_LEAF {
                nearest[std::size_t(lane)].test<decltype(kernel)::kSimd>(
                    testers.get(std::size_t(lane)), leaf_blocks(bvh_, leaf, count), range);
            });
    for (std::size_t i = 0; i < rays.size(); ++i)
        hits[i] = nearest[i].found ? std::optional<ShapeHit>(nearest[i].hit) : std::nullopt;
}

unsigned MeshBvh::occluded_packet(std::span<const Ray> rays, const Interval* t_ranges) const {
    assert(rays.size() <= std::size_t(kRayPacketSize));
    PacketTesters testers(rays);
    return bvh_any_leaf_packet(
        bvh_, rays, t_ranges,
        [&](auto kernel, std::uint32_t leaf, std::uint32_t count, int lane, Interval range)
            GLINT_INLINE_LEAF {
                return blocks_occlude<decltype(kernel)::kSimd>(
                    testers.get(std::size_t(lane)), leaf_blocks(bvh_, leaf, count), range);
            });
}

namespace {

// Finds the meshes to bind, builds their trees, then copies the shapes around them.
class Binder {
public:
    explicit Binder(const std::function<bool(const Shape&)>& whole_at_top)
        : whole_at_top_(whole_at_top) {}

    void find(const Shape& shape, bool top) {
        if (const auto* mesh = std::get_if<TriangleMesh>(&shape)) {
            if ((!top || whole_at_top_(shape)) && !bvhs_.contains(mesh->data.get())) {
                bvhs_.emplace(mesh->data.get(), nullptr);
                meshes_.push_back(mesh->data);
            }
        } else if (const auto* t = std::get_if<Transformed>(&shape)) {
            find(*t->shape, false);
        } else if (const auto* m = std::get_if<Moving>(&shape)) {
            find(*m->shape, false);
        } else if (const auto* c = std::get_if<Csg>(&shape)) {
            find(*c->a, false);
            find(*c->b, false);
        }
    }

    MeshBvhBinding build() {
        std::vector<std::shared_ptr<const MeshBvh>> built(meshes_.size());
        tbb::parallel_for(std::size_t(0), meshes_.size(), [&](std::size_t i) {
            built[i] = std::make_shared<const MeshBvh>(meshes_[i]);
        });
        MeshBvhBinding binding{meshes_.size(), 0};
        for (std::size_t i = 0; i < meshes_.size(); ++i) {
            binding.memory_bytes += built[i]->tree().memory_bytes();
            bvhs_[meshes_[i].get()] = std::move(built[i]);
        }
        return binding;
    }

    // The shape with its meshes bound, or nothing when it holds none to bind.
    std::optional<Shape> bound(const Shape& shape, bool top) {
        if (const auto* mesh = std::get_if<TriangleMesh>(&shape)) {
            const auto found = bvhs_.find(mesh->data.get());
            if (found == bvhs_.end() || (top && !whole_at_top_(shape))) return std::nullopt;
            TriangleMesh copy = *mesh;
            copy.accelerator = found->second;
            return copy;
        }
        if (const auto* t = std::get_if<Transformed>(&shape))
            return rebuilt(*t, &Transformed::shape);
        if (const auto* m = std::get_if<Moving>(&shape)) return rebuilt(*m, &Moving::shape);
        if (const auto* c = std::get_if<Csg>(&shape)) {
            auto a = bound_child(c->a), b = bound_child(c->b);
            if (!a && !b) return std::nullopt;
            Csg copy = *c;
            if (a) copy.a = std::move(a);
            if (b) copy.b = std::move(b);
            return copy;
        }
        return std::nullopt;
    }

private:
    template <typename Holder>
    std::optional<Shape> rebuilt(const Holder& holder,
                                 std::shared_ptr<const Shape> Holder::*child) {
        auto bound = bound_child(holder.*child);
        if (!bound) return std::nullopt;
        Holder copy = holder;
        copy.*child = std::move(bound);
        return copy;
    }

    // One copy of each shared child, however many shapes hold it.
    std::shared_ptr<const Shape> bound_child(const std::shared_ptr<const Shape>& child) {
        if (const auto done = copies_.find(child.get()); done != copies_.end()) return done->second;
        std::optional<Shape> copy = bound(*child, false);
        auto result = copy ? std::make_shared<const Shape>(std::move(*copy)) : nullptr;
        copies_.emplace(child.get(), result);
        return result;
    }

    const std::function<bool(const Shape&)>& whole_at_top_;
    std::vector<std::shared_ptr<const MeshData>> meshes_;
    std::unordered_map<const MeshData*, std::shared_ptr<const MeshBvh>> bvhs_;
    std::unordered_map<const Shape*, std::shared_ptr<const Shape>> copies_;
};

}  // namespace

MeshBvhBinding bind_mesh_bvhs(std::span<Primitive> primitives,
                              const std::function<bool(const Shape&)>& whole_at_top) {
    Binder binder(whole_at_top);
    for (const Primitive& p : primitives) binder.find(p.shape, true);
    const MeshBvhBinding binding = binder.build();
    for (Primitive& p : primitives)
        if (std::optional<Shape> bound = binder.bound(p.shape, true)) p.shape = std::move(*bound);
    return binding;
}

}  // namespace glint
