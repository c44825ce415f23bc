// The wide BVH (WideBvh) against the binary BVH it is collapsed from, on the same rays: the ray
// sets of `glint bench` (primary, incoherent, shadow) of SPD databases and meshes, traced through
// the triangles of the scene's largest mesh (the bottom level) and over the scene's primitives (the
// top level); and build times, single thread and all threads, against Embree's where it is built
// in. Scenes come from ../shared/data (skipped when absent). Ratios are in bench/README.md.
#include <benchmark/benchmark.h>
#include <tbb/global_control.h>
#include <tbb/info.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <bit>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "glint/accel/bvh.h"
#ifdef GLINT_HAVE_EMBREE
#include <embree3/rtcore.h>

#include "glint/accel/embree_aggregate.h"
#endif
#include "glint/accel/make_aggregate.h"
#include "glint/accel/mesh_bvh.h"
#include "glint/accel/rounding_margin.h"
#include "glint/accel/wide_bvh.h"
#include "glint/accel/wide_bvh_packet.h"
#include "glint/accel/wide_bvh_traversal.h"
#include "glint/geometry/simd_path.h"
#include "glint/render/ray_sets.h"
#include "glint/render/world.h"
#include "glint/scene/load_scene.h"

namespace glint {
namespace {

const std::filesystem::path kData = std::filesystem::path(GLINT_SOURCE_DIR) / "../shared/data";
constexpr std::size_t kRaysPerSet = std::size_t(1) << 17;

// Everything one scene's benchmarks share, made once.
struct Subject {
    Scene scene;
    std::unique_ptr<World> world;
    RaySets sets;
    // Bottom level: the largest mesh, its triangle boxes and both trees over them.
    std::shared_ptr<const MeshData> mesh;
    std::vector<Bounds3> triangle_bounds;
    Bvh mesh_binary;
    std::unique_ptr<MeshBvh> mesh_wide;
    // Top level: the bounded primitives' boxes, grown as BvhAggregate grows them.
    std::vector<std::uint32_t> bounded;
    std::vector<Bounds3> primitive_bounds;
    Bvh top_binary;
    WideBvh top_wide;
#ifdef GLINT_HAVE_EMBREE
    std::unique_ptr<class EmbreeMesh> embree_mesh;  // made when first traced
#endif
};

std::vector<Bounds3> triangle_boxes(const MeshData& mesh) {
    std::vector<Bounds3> out;
    out.reserve(mesh.triangles.size());
    for (const auto& t : mesh.triangles)
        out.push_back(
            merge(Bounds3::of(mesh.positions[t[0]], mesh.positions[t[1]]), mesh.positions[t[2]]));
    return out;
}

Subject* subject(const std::string& file) {
    static std::map<std::string, std::unique_ptr<Subject>> cache;
    auto& slot = cache[file];
    if (slot) return slot.get();
    const std::filesystem::path path = kData / file;
    if (!std::filesystem::exists(path)) return nullptr;
    auto s = std::make_unique<Subject>();
    s->scene = load_scene(path);
    s->world = std::make_unique<World>(s->scene);
    s->sets = make_ray_sets(*s->world, kRaysPerSet);
    Bounds3 all;
    for (std::uint32_t i = 0; i < s->world->primitives().size(); ++i) {
        const Primitive& p = s->world->primitives()[i];
        if (const auto* m = std::get_if<TriangleMesh>(&p.shape)) {
            if (!s->mesh || m->data->triangles.size() > s->mesh->triangles.size())
                s->mesh = m->data;
        }
        const Bounds3 b = bounds(p.shape);
        if (!b.is_finite()) continue;
        s->bounded.push_back(i);
        s->primitive_bounds.push_back(b);
        all = merge(all, b);
    }
    const float margin = rounding_margin(all);
    for (Bounds3& b : s->primitive_bounds)
        b = {b.min - Vector3{margin, margin, margin}, b.max + Vector3{margin, margin, margin}};
    s->top_binary = build_bvh(s->primitive_bounds);
    s->top_wide = build_wide_bvh(s->primitive_bounds);
    if (s->mesh) {
        s->triangle_bounds = triangle_boxes(*s->mesh);
        s->mesh_binary = build_bvh(s->triangle_bounds);
        s->mesh_wide = std::make_unique<MeshBvh>(s->mesh);
    }
    slot = std::move(s);
    return slot.get();
}

enum class Tree { binary, wide, packet, embree_single, embree_packet };

// Traces one set through the binary tree, one triangle at a time; returns the hits (to check
// that the trees agree).
std::size_t trace_mesh(const Bvh& bvh, const MeshData& mesh, const RaySet& set) {
    std::size_t hits = 0;
    for (std::size_t i = 0; i < set.rays.size(); ++i) {
        const Ray& ray = set.rays[i];
        if (set.query == RayQuery::occluded) {
            hits += bvh_any_hit(bvh, ray, set.range(i), [&](std::uint32_t k, Interval r) {
                return intersect_triangle(mesh, k, ray, r).has_value();
            });
        } else {
            hits += bvh_closest_hit(bvh, ray, set.range(i),
                                    [&](std::uint32_t k, Interval r) -> std::optional<float> {
                                        const auto hit = intersect_triangle(mesh, k, ray, r);
                                        if (!hit) return std::nullopt;
                                        return hit->t;
                                    })
                        .has_value();
        }
    }
    return hits;
}

// The same through the mesh's own wide tree, whose leaves test four triangles at a time.
std::size_t trace_mesh(const MeshBvh& mesh, const RaySet& set) {
    std::size_t hits = 0;
    for (std::size_t i = 0; i < set.rays.size(); ++i) {
        hits += set.query == RayQuery::occluded
                    ? mesh.occluded(set.rays[i], set.range(i))
                    : mesh.intersect(set.rays[i], set.range(i)).has_value();
    }
    return hits;
}

// The order in which a set's rays go into packets of eight: primary rays in tiles of 4x2 pixels,
// the others as they come (the surface points of neighbouring pixels in scanline order).
std::vector<std::size_t> packet_order(const RaySet& set, int width) {
    std::vector<std::size_t> order(set.rays.size());
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    if (set.name != "primary" || width <= 0) return order;
    std::size_t k = 0;
    const auto w = std::size_t(width), h = set.rays.size() / w;
    for (std::size_t y = 0; y < h; y += 2)
        for (std::size_t x = 0; x < w; x += 4)
            for (std::size_t dy = 0; dy < 2 && y + dy < h; ++dy)
                for (std::size_t dx = 0; dx < 4 && x + dx < w; ++dx)
                    order[k++] = (y + dy) * w + x + dx;
    return order;
}

// The same in packets of eight neighbouring rays (wide_bvh_packet.h), in packet_order.
std::size_t trace_mesh_packets(const MeshBvh& mesh, const RaySet& set, int width) {
    const std::vector<std::size_t> order = packet_order(set, width);
    std::size_t hits = 0;
    for (std::size_t first = 0; first < order.size(); first += kRayPacketSize) {
        const std::size_t n = std::min(order.size() - first, std::size_t(kRayPacketSize));
        Ray rays[kRayPacketSize];
        Interval ranges[kRayPacketSize];
        for (std::size_t i = 0; i < n; ++i) {
            rays[i] = set.rays[order[first + i]];
            ranges[i] = set.range(order[first + i]);
        }
        if (set.query == RayQuery::occluded) {
            hits += std::size_t(std::popcount(mesh.occluded_packet({rays, n}, ranges)));
        } else {
            std::optional<ShapeHit> found[kRayPacketSize];
            mesh.intersect_packet({rays, n}, ranges, found);
            for (std::size_t i = 0; i < n; ++i) hits += found[i].has_value();
        }
    }
    return hits;
}

#ifdef GLINT_HAVE_EMBREE
// The mesh as one Embree triangle geometry, built as EmbreeAggregate builds it (robust, high
// quality), for Embree's single-ray and packet API on the same rays.
class EmbreeMesh {
public:
    explicit EmbreeMesh(const MeshData& mesh) {
        device_ = rtcNewDevice(nullptr);
        scene_ = rtcNewScene(device_);
        rtcSetSceneFlags(scene_, RTC_SCENE_FLAG_ROBUST);
        rtcSetSceneBuildQuality(scene_, RTC_BUILD_QUALITY_HIGH);
        RTCGeometry g = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_TRIANGLE);
        auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(
            g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 12, mesh.positions.size()));
        for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
            v[3 * i] = mesh.positions[i].x;
            v[3 * i + 1] = mesh.positions[i].y;
            v[3 * i + 2] = mesh.positions[i].z;
        }
        auto* t = static_cast<std::uint32_t*>(rtcSetNewGeometryBuffer(
            g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 12, mesh.triangles.size()));
        for (std::size_t i = 0; i < mesh.triangles.size(); ++i)
            for (int k = 0; k < 3; ++k)
                t[3 * i + std::size_t(k)] = mesh.triangles[i][std::size_t(k)];
        rtcCommitGeometry(g);
        rtcAttachGeometry(scene_, g);
        rtcReleaseGeometry(g);
        rtcCommitScene(scene_);
    }
    ~EmbreeMesh() {
        rtcReleaseScene(scene_);
        rtcReleaseDevice(device_);
    }
    EmbreeMesh(const EmbreeMesh&) = delete;
    EmbreeMesh& operator=(const EmbreeMesh&) = delete;

    std::size_t trace_single(const RaySet& set) const {
        RTCIntersectContext context;
        rtcInitIntersectContext(&context);
        std::size_t hits = 0;
        for (std::size_t i = 0; i < set.rays.size(); ++i) {
            RTCRayHit rh{};
            fill(rh.ray, set.rays[i], set.range(i));
            if (set.query == RayQuery::occluded) {
                rtcOccluded1(scene_, &context, &rh.ray);
                hits += rh.ray.tfar < 0;
            } else {
                rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
                rtcIntersect1(scene_, &context, &rh);
                hits += rh.hit.geomID != RTC_INVALID_GEOMETRY_ID;
            }
        }
        return hits;
    }

    std::size_t trace_packets(const RaySet& set, int width) const {
        const std::vector<std::size_t> order = packet_order(set, width);
        RTCIntersectContext context;
        rtcInitIntersectContext(&context);
        context.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
        std::size_t hits = 0;
        for (std::size_t first = 0; first < order.size(); first += 8) {
            alignas(32) int valid[8];
            alignas(32) RTCRayHit8 rh{};
            for (int l = 0; l < 8; ++l) {
                const std::size_t k = first + std::size_t(l);
                valid[l] = k < order.size() ? -1 : 0;
                const std::size_t i = order[std::min(k, order.size() - 1)];
                const Ray& r = set.rays[i];
                const Interval range = set.range(i);
                rh.ray.org_x[l] = r.origin.x, rh.ray.org_y[l] = r.origin.y;
                rh.ray.org_z[l] = r.origin.z;
                rh.ray.dir_x[l] = r.direction.x, rh.ray.dir_y[l] = r.direction.y;
                rh.ray.dir_z[l] = r.direction.z;
                rh.ray.tnear[l] = std::max(range.min, 0.0f);
                rh.ray.tfar[l] = range.max;
                rh.ray.mask[l] = 0xffffffffu;
                rh.hit.geomID[l] = RTC_INVALID_GEOMETRY_ID;
            }
            if (set.query == RayQuery::occluded) {
                rtcOccluded8(valid, scene_, &context, &rh.ray);
                for (int l = 0; l < 8; ++l) hits += valid[l] && rh.ray.tfar[l] < 0;
            } else {
                rtcIntersect8(valid, scene_, &context, &rh);
                for (int l = 0; l < 8; ++l)
                    hits += valid[l] && rh.hit.geomID[l] != RTC_INVALID_GEOMETRY_ID;
            }
        }
        return hits;
    }

private:
    static void fill(RTCRay& out, const Ray& r, Interval range) {
        out.org_x = r.origin.x, out.org_y = r.origin.y, out.org_z = r.origin.z;
        out.dir_x = r.direction.x, out.dir_y = r.direction.y, out.dir_z = r.direction.z;
        out.tnear = std::max(range.min, 0.0f);
        out.tfar = range.max;
        out.mask = 0xffffffffu;
        out.flags = 0;
        out.time = 0;
    }

    RTCDevice device_;
    RTCScene scene_;
};
#endif

template <typename BvhType>
std::size_t trace_top(const BvhType& bvh, const Subject& s, const RaySet& set) {
    const std::span<const Primitive> prims = s.world->primitives();
    std::size_t hits = 0;
    for (std::size_t i = 0; i < set.rays.size(); ++i) {
        const Ray& ray = set.rays[i];
        if (set.query == RayQuery::occluded) {
            hits += bvh_any_hit(bvh, ray, set.range(i), [&](std::uint32_t k, Interval r) {
                const Primitive& p = prims[s.bounded[k]];
                return (p.visibility & set.mask) != 0 && intersect(p.shape, ray, r).has_value();
            });
        } else {
            hits += bvh_closest_hit(bvh, ray, set.range(i),
                                    [&](std::uint32_t k, Interval r) -> std::optional<float> {
                                        const Primitive& p = prims[s.bounded[k]];
                                        if ((p.visibility & set.mask) == 0) return std::nullopt;
                                        const auto hit = intersect(p.shape, ray, r);
                                        if (!hit) return std::nullopt;
                                        return hit->t;
                                    })
                        .has_value();
        }
    }
    return hits;
}

void traverse(benchmark::State& state, const std::string& file, bool mesh_level,
              std::size_t set_index, Tree tree, SimdPath path) {
    Subject* s = subject(file);
    if (!s || (mesh_level && !s->mesh) || set_index >= s->sets.sets.size()) {
        state.SkipWithError("scene or mesh not available");
        return;
    }
    if (!set_simd_path(path)) {
        state.SkipWithError("SIMD path not supported here");
        return;
    }
    const RaySet& set = s->sets.sets[set_index];
    std::size_t hits = 0;
    for (auto _ : state) {
        if (mesh_level) {
            switch (tree) {
                case Tree::binary:
                    hits = trace_mesh(s->mesh_binary, *s->mesh, set);
                    break;
                case Tree::wide:
                    hits = trace_mesh(*s->mesh_wide, set);
                    break;
                case Tree::packet:
                    hits = trace_mesh_packets(*s->mesh_wide, set, s->sets.width);
                    break;
                case Tree::embree_single:
                case Tree::embree_packet:
#ifdef GLINT_HAVE_EMBREE
                    if (!s->embree_mesh) s->embree_mesh = std::make_unique<EmbreeMesh>(*s->mesh);
                    hits = tree == Tree::embree_single
                               ? s->embree_mesh->trace_single(set)
                               : s->embree_mesh->trace_packets(set, s->sets.width);
#endif
                    break;
            }
        } else {
            hits = tree == Tree::binary ? trace_top(s->top_binary, *s, set)
                                        : trace_top(s->top_wide, *s, set);
        }
        benchmark::DoNotOptimize(hits);
    }
    set_simd_path(best_simd_path());
    state.SetItemsProcessed(std::int64_t(state.iterations() * set.rays.size()));
    state.counters["hits"] = double(hits);
    if (mesh_level) {
        const MeshData& m = *s->mesh;
        const double tris = double(m.triangles.size());
        const std::size_t binary_bytes = s->mesh_binary.nodes.size() * sizeof(BvhNode) +
                                         s->mesh_binary.primitive_indices.size() * 4;
        state.counters["tree_bytes_per_tri"] =
            double(tree == Tree::binary ? binary_bytes : s->mesh_wide->tree().memory_bytes()) /
            tris;
        // Everything the mesh takes: positions, normals, uvs, indices and the tree.
        const std::size_t arrays = m.positions.size() * sizeof(Point3) +
                                   m.normals.size() * sizeof(Normal3) +
                                   m.uvs.size() * sizeof(Point2) + m.triangles.size() * 12;
        state.counters["all_bytes_per_tri"] =
            double(arrays + s->mesh_wide->tree().memory_bytes()) / tris;
    }
}

template <typename F>
double seconds_on(int threads, F&& f) {
    tbb::global_control allow(tbb::global_control::max_allowed_parallelism, std::size_t(threads));
    tbb::task_arena arena(threads);
    double seconds = 0;
    arena.execute([&] {
        const auto start = std::chrono::steady_clock::now();
        f();
        seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    });
    return seconds;
}

enum class Build { binary, collapse, wide, scene_wide, scene_embree, scene_embree_medium };

// Builds over the scene's largest mesh (binary; collapse: the binary tree made wide, its build not
// timed; wide: the mesh's own tree of triangle blocks), or the whole scene as the renderer needs
// it (scene_wide: the scene-level tree over all primitives and triangles; scene_embree: Embree's
// one BVH over the same, at the high quality glint asks of it, or at medium quality, binned SAH
// without spatial splits as glint's own build). Manual time: the build alone, on `threads`.
void build(benchmark::State& state, const std::string& file, Build what, int threads) {
    Subject* s = subject(file);
    const bool scene_level = what == Build::scene_wide || what == Build::scene_embree ||
                             what == Build::scene_embree_medium;
    if (!s || (!scene_level && !s->mesh)) {
        state.SkipWithError("scene or mesh not available");
        return;
    }
    const std::span<const Primitive> prims = s->world->primitives();
    for (auto _ : state) {
        Bvh binary;
        if (what == Build::collapse) binary = s->mesh_binary;
        const double seconds = seconds_on(threads, [&] {
            switch (what) {
                case Build::binary:
                    benchmark::DoNotOptimize(build_bvh(s->triangle_bounds).nodes.data());
                    break;
                case Build::collapse:
                    benchmark::DoNotOptimize(collapse_to_wide_bvh(std::move(binary)).nodes.data());
                    break;
                case Build::wide:
                    benchmark::DoNotOptimize(MeshBvh(s->mesh).tree().nodes.data());
                    break;
                case Build::scene_wide:
                    benchmark::DoNotOptimize(make_aggregate(AccelKind::bvh, prims).get());
                    break;
                case Build::scene_embree:
                    benchmark::DoNotOptimize(make_aggregate(AccelKind::embree, prims).get());
                    break;
                case Build::scene_embree_medium:
#ifdef GLINT_HAVE_EMBREE
                    benchmark::DoNotOptimize(
                        std::make_unique<EmbreeAggregate>(prims, EmbreeBuildQuality::medium).get());
#endif
                    break;
            }
        });
        state.SetIterationTime(seconds);
    }
    state.counters["triangles"] = double(s->mesh ? s->mesh->triangles.size() : 0);
}

void register_all() {
    std::vector<std::string> scenes = {"spd/teapot-s30.nff.gz", "spd/tetra-s9.nff.gz",
                                       "spd/balls.nff", "meshes/stanford-bunny.obj",
                                       "meshes/fandisk.obj"};
    // More meshes by path (such as bench/subdivide_obj.py's), separated by ':'.
    if (const char* extra = std::getenv("GLINT_BVH_BENCH_MESHES")) {
        std::stringstream list(extra);
        for (std::string path; std::getline(list, path, ':');)
            if (!path.empty()) scenes.push_back(path);
    }
    const char* const set_names[] = {"primary", "incoherent", "shadow"};
    for (const std::string& file : scenes) {
        const std::string name = std::filesystem::path(file).filename().string();
        // Meshes at the bottom level; the SPD balls (spheres) at the top.
        const bool mesh_level = name != "balls.nff";
        for (std::size_t set = 0; set < 3; ++set) {
            const std::string prefix =
                std::string(mesh_level ? "Mesh/" : "Top/") + name + "/" + set_names[set] + "/";
            benchmark::RegisterBenchmark((prefix + "binary").c_str(), traverse, file, mesh_level,
                                         set, Tree::binary, SimdPath::scalar);
            for (const SimdPath path : kSimdPaths)
                benchmark::RegisterBenchmark(
                    (prefix + "wide_" + std::string(simd_path_name(path))).c_str(), traverse, file,
                    mesh_level, set, Tree::wide, path);
            if (mesh_level) {
                benchmark::RegisterBenchmark((prefix + "packet8_avx2").c_str(), traverse, file,
                                             mesh_level, set, Tree::packet, SimdPath::avx2);
#ifdef GLINT_HAVE_EMBREE
                benchmark::RegisterBenchmark((prefix + "embree_single").c_str(), traverse, file,
                                             mesh_level, set, Tree::embree_single,
                                             best_simd_path());
                benchmark::RegisterBenchmark((prefix + "embree_packet8").c_str(), traverse, file,
                                             mesh_level, set, Tree::embree_packet,
                                             best_simd_path());
#endif
            }
        }
        const int all = tbb::info::default_concurrency();
        for (const int threads : {1, all}) {
            if (threads == all && all == 1) continue;
            const std::string suffix = "/threads:" + std::to_string(threads);
            if (mesh_level) {
                benchmark::RegisterBenchmark(("Build/" + name + "/mesh_binary" + suffix).c_str(),
                                             build, file, Build::binary, threads)
                    ->UseManualTime()
                    ->Unit(benchmark::kMillisecond);
                benchmark::RegisterBenchmark(("Build/" + name + "/mesh_collapse" + suffix).c_str(),
                                             build, file, Build::collapse, threads)
                    ->UseManualTime()
                    ->Unit(benchmark::kMillisecond);
                benchmark::RegisterBenchmark(("Build/" + name + "/mesh_wide" + suffix).c_str(),
                                             build, file, Build::wide, threads)
                    ->UseManualTime()
                    ->Unit(benchmark::kMillisecond);
            }
            benchmark::RegisterBenchmark(("Build/" + name + "/scene_wide" + suffix).c_str(), build,
                                         file, Build::scene_wide, threads)
                ->UseManualTime()
                ->Unit(benchmark::kMillisecond);
#ifdef GLINT_HAVE_EMBREE
            benchmark::RegisterBenchmark(("Build/" + name + "/scene_embree" + suffix).c_str(),
                                         build, file, Build::scene_embree, threads)
                ->UseManualTime()
                ->Unit(benchmark::kMillisecond);
            benchmark::RegisterBenchmark(
                ("Build/" + name + "/scene_embree_medium" + suffix).c_str(), build, file,
                Build::scene_embree_medium, threads)
                ->UseManualTime()
                ->Unit(benchmark::kMillisecond);
#endif
        }
    }
}

}  // namespace
}  // namespace glint

int main(int argc, char** argv) {
    glint::register_all();
    benchmark::Initialize(&argc, argv);
    benchmark::RunSpecifiedBenchmarks();
    return 0;
}
