// Every acceleration structure that accel_names() lists returns exactly the brute-force list's
// closest hits (same t, same primitive) and occlusion answers, on random and adversarial input;
// and, asked for rays in packets, each ray's own hit bit for bit.
// Embree is the exception: its own triangle test differs in the last bits, so
// embree_aggregate_test.cpp compares it with a tolerance instead.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "common/under_sanitizer.h"
#include "glint/accel/make_aggregate.h"
#include "glint/accel/primitive_list.h"
#include "glint/geometry/simd_path.h"
#include "glint/math/constants.h"

namespace glint {
namespace {

constexpr std::uint32_t kMasks[] = {kVisibleToCameraRays, kVisibleToShadowRays};

// Every structure built over one scene, checked ray by ray against the list.
class Agreement {
public:
    explicit Agreement(std::span<const Primitive> primitives) : list_(primitives) {
        for (const std::string_view name : accel_names()) {
            if (name == "embree") continue;  // its own triangle test: checked on its own
            auto aggregate = make_aggregate(*accel_from_name(name), primitives);
            EXPECT_TRUE(aggregate) << name;
            if (aggregate) structures_.push_back({std::string(name), std::move(aggregate)});
        }
    }

    // Compares closest hits and occlusion for both ray masks over `range`; counts the list's
    // hits. `what` names the ray in failure messages.
    void check(const Ray& ray, Interval range, const std::string& what) {
        for (const std::uint32_t mask : kMasks) {
            const std::optional<Hit> expected = list_.intersect(ray, range, mask);
            const bool expected_occluded = list_.occluded(ray, range, mask);
            hits_ += expected.has_value();
            for (const auto& [name, aggregate] : structures_) {
                const std::optional<Hit> got = aggregate->intersect(ray, range, mask);
                ASSERT_EQ(got.has_value(), expected.has_value()) << name << ", " << what;
                if (got) {
                    ASSERT_EQ(got->shape_hit.t, expected->shape_hit.t) << name << ", " << what;
                    ASSERT_EQ(got->primitive, expected->primitive) << name << ", " << what;
                }
                ASSERT_EQ(aggregate->occluded(ray, range, mask), expected_occluded)
                    << name << ", " << what;
            }
        }
        // Each ray also joins a packet of the rays checked before it over the same range.
        auto packet = std::find_if(packets_.begin(), packets_.end(),
                                   [&](const Packet& p) { return same_range(p.range, range); });
        if (packet == packets_.end()) packet = packets_.insert(packets_.end(), {range, {}});
        packet->rays.push_back(ray);
        if (packet->rays.size() == std::size_t(kRayPacketSize)) {
            check_packet(packet->rays, range, "a packet");
            packets_.erase(packet);
        }
    }

    // Every structure's hits for `rays` asked as one packet, lane by lane against the same
    // structure's hit for the ray alone: the same t, u, v, part and primitive; and whether each
    // is blocked, every third lane's range cut short.
    void check_packet(std::span<const Ray> rays, Interval range, const std::string& what) {
        Interval ranges[kRayPacketSize];
        for (std::size_t i = 0; i < rays.size(); ++i)
            ranges[i] = i % 3 == 2 ? Interval{range.min, std::min(range.max, 10.0f)} : range;
        for (const std::uint32_t mask : kMasks)
            for (const auto& [name, aggregate] : structures_) {
                std::optional<Hit> got[kRayPacketSize];
                aggregate->intersect_packet(rays, range, mask, got);
                const unsigned blocked = aggregate->occluded_packet(rays, ranges, mask);
                ASSERT_EQ(blocked >> rays.size(), 0u) << name << ", " << what;
                for (std::size_t i = 0; i < rays.size(); ++i) {
                    const std::optional<Hit> alone = aggregate->intersect(rays[i], range, mask);
                    const std::string where = name + ", " + what + ", lane " + std::to_string(i);
                    ASSERT_EQ(bool(blocked >> i & 1), aggregate->occluded(rays[i], ranges[i], mask))
                        << where;
                    packet_blocked_ += blocked >> i & 1;
                    ASSERT_EQ(got[i].has_value(), alone.has_value()) << where;
                    if (!alone) continue;
                    ++packet_hits_;
                    ASSERT_EQ(got[i]->shape_hit.t, alone->shape_hit.t) << where;
                    ASSERT_EQ(got[i]->shape_hit.u, alone->shape_hit.u) << where;
                    ASSERT_EQ(got[i]->shape_hit.v, alone->shape_hit.v) << where;
                    ASSERT_EQ(got[i]->shape_hit.part, alone->shape_hit.part) << where;
                    ASSERT_EQ(got[i]->primitive, alone->primitive) << where;
                }
            }
    }
    ~Agreement() {
        for (const Packet& p : packets_) check_packet(p.rays, p.range, "a last packet");
    }

    int hits() const { return hits_; }
    int packet_hits() const { return packet_hits_; }
    int packet_blocked() const { return packet_blocked_; }
    std::size_t structure_count() const { return structures_.size(); }
    const PrimitiveList& list() const { return list_; }

private:
    struct Named {
        std::string name;
        std::unique_ptr<Aggregate> aggregate;
    };
    static bool same_range(Interval a, Interval b) {
        return (a.min == b.min || (std::isnan(a.min) && std::isnan(b.min))) && a.max == b.max;
    }

    PrimitiveList list_;
    std::vector<Named> structures_;
    int hits_ = 0;
    int packet_hits_ = 0;
    int packet_blocked_ = 0;
    // Rays checked alone, waiting to be checked as a packet with others over the same range.
    struct Packet {
        Interval range;
        std::vector<Ray> rays;
    };
    std::vector<Packet> packets_;
};

std::string ray_text(const Ray& r, int i) {
    return "ray " + std::to_string(i) + " o=(" + std::to_string(r.origin.x) + ", " +
           std::to_string(r.origin.y) + ", " + std::to_string(r.origin.z) + ") d=(" +
           std::to_string(r.direction.x) + ", " + std::to_string(r.direction.y) + ", " +
           std::to_string(r.direction.z) + ")";
}

Vector3 random_direction(std::mt19937& rng) {
    std::normal_distribution<float> g;
    for (;;) {
        const Vector3 d{g(rng), g(rng), g(rng)};
        if (length_squared(d) > 1e-6f) return normalize(d);
    }
}

// Spheres, boxes, triangles (a few degenerate: collinear or all in one point) and planes, of
// sizes from tiny to a tenth of the scene and a few large ones; some cast no shadows.
std::vector<Primitive> random_mix(int n, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> pos(-10, 10), unit(0, 1);
    std::vector<Primitive> prims;
    for (int i = 0; i < n; ++i) {
        const Point3 c{pos(rng), pos(rng), pos(rng)};
        const float s = i % 97 == 0 ? 6.0f : 0.02f + 1.5f * unit(rng) * unit(rng);
        Primitive p;
        switch (i % 4) {
            case 0:
                p.shape = Sphere{c, s};
                break;
            case 1:
                p.shape = Box{c, c + Vector3{s, s * (0.1f + unit(rng)), s * 2}};
                break;
            case 2:
                p.shape =
                    Triangle{{c, c + s * random_direction(rng), c + s * random_direction(rng)}};
                break;
            default:
                if (i % 40 == 3) {
                    p.shape = Triangle{{c, c + Vector3{s, s, 0}, c + Vector3{2 * s, 2 * s, 0}}};
                } else if (i % 40 == 7) {
                    p.shape = Triangle{{c, c, c}};
                } else {
                    p.shape = Triangle{{c, c + Vector3{s, 0, 0}, c + Vector3{0, s, s}}};
                }
        }
        if (unit(rng) < 0.2f)
            p.visibility = unit(rng) < 0.5f ? kVisibleToCameraRays : kVisibleToShadowRays;
        prims.push_back(p);
    }
    prims.push_back({Plane{{0, -11, 0}, {0, 1, 0}}});
    prims.push_back({Plane{{12, 0, 0}, normalize(Normal3{-1, 0.2f, 0.1f})}, kVisibleToCameraRays});
    return prims;
}

TEST(AggregateProperties, EveryStructureIsListed) {
    const auto names = accel_names();
    for (const char* name : {"bvh", "grid", "kdtree", "list"})
        EXPECT_NE(std::find(names.begin(), names.end(), name), names.end()) << name;
}

TEST(AggregateProperties, RandomRaysOverRandomScenes) {
    for (const unsigned seed : {1u, 2u}) {
        const auto prims = random_mix(3000, seed);
        Agreement agree(prims);
        std::mt19937 rng(seed + 100);
        std::uniform_real_distribution<float> u(-1, 1), unit(0, 1);
        const int rays = testing::kUnderSanitizer ? 600 : 1500;
        for (int i = 0; i < rays; ++i) {
            // Origins inside the scene and up to a few scene sizes away.
            const float reach = i % 3 == 0 ? 40.0f : 12.0f;
            const Ray ray{{u(rng) * reach, u(rng) * reach, u(rng) * reach}, random_direction(rng)};
            agree.check(ray, {}, ray_text(ray, i));
            // An interval that ends, or starts and ends, inside the scene.
            agree.check(ray, {0, 15 * unit(rng)}, ray_text(ray, i) + " short");
            const float start = 10 * unit(rng);
            agree.check(ray, {start, start + 3 * unit(rng)}, ray_text(ray, i) + " segment");
            if (HasFatalFailure()) return;
        }
        EXPECT_GT(agree.hits(), rays);
    }
}

TEST(AggregateProperties, MovingShapesAtRandomTimes) {
    // Spheres and boxes that slide, turn and grow between keyframes at times 0, 0.5 and 1: every
    // structure bounds them over the motion and finds them where each ray's time puts them.
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> pos(-10, 10), unit(0, 1), u(-1, 1);
    std::vector<Primitive> prims;
    for (int i = 0; i < 600; ++i) {
        const Point3 c{pos(rng), pos(rng), pos(rng)};
        const float s = 0.1f + unit(rng);
        const Shape still =
            i % 2 == 0 ? Shape{Sphere{{0, 0, 0}, s}} : Shape{Box{{-s, -s, -s}, {s, s, s * 2}}};
        const Vector3 slide{3 * u(rng), 3 * u(rng), 3 * u(rng)};
        const auto motion = std::make_shared<const AnimatedTransform>(std::vector<Keyframe>{
            {0, Transform::translate(to_vector(c))},
            {0.5f, Transform::translate(to_vector(c) + slide) *
                       Transform::rotate(random_direction(rng), 170 * unit(rng))},
            {1, Transform::translate(to_vector(c) - slide) * Transform::scale(1.5f, 1, 0.5f)}});
        prims.push_back({Moving{motion, std::make_shared<const Shape>(still)}});
    }
    Agreement agree(prims);
    int hits_at_other_times = 0;
    // Interpolating 600 transforms a ray is slow under the sanitizers (44 s for 1,200 rays).
    const int rays = testing::kUnderSanitizer ? 400 : 1200;
    for (int i = 0; i < rays; ++i) {
        Ray ray{{u(rng) * 15, u(rng) * 15, u(rng) * 15}, random_direction(rng)};
        ray.time = i % 10 == 0 ? -0.5f + 2 * unit(rng) : unit(rng);  // some outside [0, 1]
        agree.check(ray, {}, ray_text(ray, i) + " time " + std::to_string(ray.time));
        // The same ray at another moment meets other things.
        const auto now = agree.list().intersect(ray, {}, kVisibleToCameraRays);
        ray.time = 1 - ray.time;
        const auto then = agree.list().intersect(ray, {}, kVisibleToCameraRays);
        hits_at_other_times += now.has_value() != then.has_value() ||
                               (now && then && now->primitive != then->primitive);
        if (HasFatalFailure()) return;
    }
    EXPECT_GT(agree.hits(), rays / 3);
    EXPECT_GT(hits_at_other_times, rays / 30);
}

TEST(AggregateProperties, AxisParallelRays) {
    const auto prims = random_mix(2000, 3);
    Agreement agree(prims);
    std::mt19937 rng(4);
    std::uniform_real_distribution<float> u(-1, 1);
    std::uniform_int_distribution<int> pick(0, 5);
    for (int i = 0; i < 2000; ++i) {
        const int k = pick(rng);
        const float sign = k % 2 ? 1.0f : -1.0f;
        Vector3 d{0, 0, 0};
        (k / 2 == 0 ? d.x : k / 2 == 1 ? d.y : d.z) = sign;
        // Integer and half-integer origins too: they line up with bounds and cell planes.
        Point3 o{u(rng) * 12, u(rng) * 12, u(rng) * 12};
        if (i % 4 == 0) o = {std::round(o.x), std::round(o.y), std::round(o.z)};
        if (i % 4 == 1) o = {std::round(2 * o.x) / 2, std::round(2 * o.y) / 2, o.z};
        const Ray ray{o, d};
        agree.check(ray, {}, ray_text(ray, i));
        if (i % 2) agree.check({o, -d}, {0, 6}, ray_text(ray, i) + " reversed, short");
        if (HasFatalFailure()) return;
    }
    EXPECT_GT(agree.hits(), 500);
}

TEST(AggregateProperties, RaysStartingOnFacesAndInsidePrimitives) {
    const auto prims = random_mix(1500, 5);
    Agreement agree(prims);
    std::mt19937 rng(6);
    std::uniform_real_distribution<float> unit(0, 1);
    int i = 0;
    for (const Primitive& p : prims) {
        Point3 starts[3];
        int count = 0;
        if (const Box* box = std::get_if<Box>(&p.shape)) {
            const Vector3 e = box->max - box->min;
            starts[count++] = {box->min.x, box->min.y + unit(rng) * e.y,
                               box->min.z + unit(rng) * e.z};
            starts[count++] = {box->min.x + unit(rng) * e.x, box->max.y,
                               box->min.z + unit(rng) * e.z};
            starts[count++] = box->min + e * 0.5f;  // inside
        } else if (const Sphere* sphere = std::get_if<Sphere>(&p.shape)) {
            starts[count++] = sphere->center;
            starts[count++] = sphere->center + random_direction(rng) * sphere->radius;
        } else if (const Triangle* tri = std::get_if<Triangle>(&p.shape)) {
            const auto& v = tri->vertices;
            const float a = unit(rng), b = unit(rng) * (1 - a);
            starts[count++] = v[0] + (v[1] - v[0]) * a + (v[2] - v[0]) * b;
            starts[count++] = v[1];  // a vertex
        }
        for (int k = 0; k < count; ++k) {
            const Ray ray{starts[k], random_direction(rng)};
            agree.check(ray, {}, ray_text(ray, i));
            agree.check(ray, {1e-4f, kInfinity}, ray_text(ray, i) + " offset");
            ++i;
        }
        if (HasFatalFailure()) return;
    }
    EXPECT_GT(agree.hits(), 500);
}

// A (flat or tilted) mesh of n x n quads, two triangles each, sharing edges and vertices, with
// a degenerate triangle along some edges; all in one plane, a flat scene for the grid.
std::vector<Primitive> triangle_grid(int n, bool tilted) {
    const auto vertex = [&](float i, float j) {
        return Point3{i, tilted ? 0.37f * i + 0.21f * j : 0.0f, j};
    };
    std::vector<Primitive> prims;
    for (int i = 0; i < n; ++i) {
        for (int j = 0; j < n; ++j) {
            const Point3 a = vertex(float(i), float(j)), b = vertex(float(i + 1), float(j));
            const Point3 c = vertex(float(i + 1), float(j + 1)), d = vertex(float(i), float(j + 1));
            prims.push_back({Triangle{{a, b, c}}});
            prims.push_back({Triangle{{a, c, d}}});
            if ((i + j) % 7 == 0) prims.push_back({Triangle{{a, b, b}}});  // zero area
        }
    }
    return prims;
}

TEST(AggregateProperties, RaysThroughSharedEdgesAndVerticesOfATriangleGrid) {
    for (const bool tilted : {false, true}) {
        const int n = 20;
        const auto prims = triangle_grid(n, tilted);
        Agreement agree(prims);
        std::mt19937 rng(7);
        std::uniform_real_distribution<float> u(-1, 1);
        std::uniform_int_distribution<int> cell(0, n);
        for (int i = 0; i < 3000; ++i) {
            // Aim at a vertex, an edge's midpoint or a diagonal's midpoint.
            float x = float(cell(rng)), z = float(cell(rng));
            if (i % 3 == 1) x += 0.5f;
            if (i % 3 == 2) x += 0.5f, z += 0.5f;
            const Point3 target{x, tilted ? 0.37f * x + 0.21f * z : 0.0f, z};
            const Point3 origin = target + Vector3{u(rng) * 10, 8 * u(rng), u(rng) * 10};
            if (length_squared(target - origin) < 1e-6f) continue;
            const Ray ray{origin, normalize(target - origin)};
            agree.check(ray, {}, ray_text(ray, i) + (tilted ? " tilted" : " flat"));
            if (HasFatalFailure()) return;
        }
        // Rays in the flat mesh's plane, along its edges and diagonals, through its vertices.
        for (int k = 0; !tilted && k <= n; ++k) {
            const float x = float(k);
            agree.check({{x, 0, -1}, {0, 0, 1}}, {}, "in-plane ray along z " + std::to_string(k));
            agree.check({{-1, 0, x}, {1, 0, 0}}, {}, "in-plane ray along x " + std::to_string(k));
            agree.check({{x - 1, 0, -1}, normalize(Vector3{1, 0, 1})}, {},
                        "in-plane diagonal ray " + std::to_string(k));
        }
        EXPECT_GT(agree.hits(), 1000);
    }
}

// A closed latitude-longitude sphere mesh as triangles of the structures themselves, the same mesh
// placed twice more as instances (each with its own BVH inside, the bottom level), and spheres
// between them.
std::vector<Primitive> meshes_instances_and_spheres() {
    MeshData arrays;
    const int n = 12;  // a latitude-longitude sphere: shared edges and vertices everywhere
    for (int i = 0; i <= n; ++i) {
        for (int j = 0; j < 2 * n; ++j) {
            const float theta = kPi * float(i) / float(n), phi = kPi * float(j) / float(n);
            arrays.positions.push_back({std::sin(theta) * std::cos(phi), std::cos(theta),
                                        std::sin(theta) * std::sin(phi)});
        }
    }
    const auto at = [&](int i, int j) { return std::uint32_t(i * 2 * n + (j % (2 * n))); };
    for (int i = 0; i < n; ++i) {
        for (int j = 0; j < 2 * n; ++j) {
            arrays.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
            arrays.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
        }
    }
    const MeshBuild built = build_mesh(std::move(arrays));
    EXPECT_TRUE(built.mesh) << built.error;
    const TriangleMesh mesh{built.mesh};
    std::vector<Primitive> prims;
    prims.push_back({Sphere{{3, 0, 0}, 0.5f}});
    prims.push_back({mesh});
    const auto shared = std::make_shared<const Shape>(Shape{mesh});
    prims.push_back({Transformed{Transform::translate({0, 0, 3}), shared}});
    prims.push_back(
        {Transformed{Transform::translate({0, 0, -3}) * Transform::scale(2, 1, 1), shared},
         kVisibleToCameraRays});
    prims.push_back({Sphere{{0, 0, 0}, 0.5f}});  // inside the first mesh
    prims.push_back({mesh});                     // the very same triangles again: ties at every t
    return prims;
}

TEST(AggregateProperties, MeshTrianglesInstancesAndSpheresInOneStructure) {
    const auto prims = meshes_instances_and_spheres();
    Agreement agree(prims);
    std::mt19937 rng(9);
    std::uniform_real_distribution<float> u(-1, 1);
    const int rays = testing::kUnderSanitizer ? 1200 : 3000;
    for (int i = 0; i < rays; ++i) {
        const Point3 origin{u(rng) * 8, u(rng) * 8, u(rng) * 8};
        // Aimed at a pole of the mesh or of an instance (a vertex of 24 triangles), or anywhere.
        const Point3 target = i % 3 == 0   ? Point3{0, 1, 0}
                              : i % 3 == 1 ? Point3{0, -1, 3}
                                           : Point3{u(rng) * 3, u(rng), u(rng) * 4};
        if (length_squared(target - origin) < 1e-6f) continue;
        const Ray ray{origin, normalize(target - origin)};
        agree.check(ray, {}, ray_text(ray, i));
        if (HasFatalFailure()) return;
    }
    // Rays from inside the mesh, through its vertices and edges.
    for (int i = 0; i < rays / 6; ++i) {
        const Ray ray{{u(rng) * 0.3f, u(rng) * 0.3f, u(rng) * 0.3f}, random_direction(rng)};
        agree.check(ray, {}, ray_text(ray, i) + " inside");
        if (HasFatalFailure()) return;
    }
    EXPECT_GT(agree.hits(), rays * 2 / 3);
    // Along z the stretched instance comes first.
    const auto hit = agree.list().intersect({{0, 0, -10}, {0, 0, 1}}, {}, ~0u);
    ASSERT_TRUE(hit);
    EXPECT_EQ(hit->primitive, 3u);  // the stretched instance at z = -3, met at t = 6
    EXPECT_FLOAT_EQ(hit->shape_hit.t, 6);
}

// Packets of neighbouring eye rays (tiles of 4 x 2 pixels, as a render traces them), of every
// size from one ray to eight, with a ray that cannot be traced among them now and then, on every
// SIMD path: the packet traversal on AVX2, one ray after another elsewhere.
TEST(AggregateProperties, PacketsOfEyeRaysHitWhatEachRayHitsAlone) {
    const auto mix = random_mix(2000, 12);
    const auto meshes = meshes_instances_and_spheres();
    std::mt19937 rng(13);
    std::uniform_real_distribution<float> u(-1, 1);
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const SimdPath saved = simd_path();
    for (const SimdPath path : kSimdPaths) {
        if (!set_simd_path(path)) continue;
        for (const auto* prims : {&mix, &meshes}) {
            Agreement agree(*prims);
            const int packets = testing::kUnderSanitizer ? 100 : 300;
            for (int n = 0; n < packets; ++n) {
                // Aimed into the scene: the meshes lie within 1.5 of the origin.
                const float spread = prims == &mix ? 8.0f : 1.5f;
                const Point3 eye{u(rng) * 3, u(rng) * 3, 25};
                const Vector3 centre = (Point3{u(rng) * spread, u(rng) * spread, 0} - eye) / 25;
                const float pixel = n % 2 ? 0.002f : 0.02f;
                const std::size_t size = n % 4 == 3 ? std::size_t(1 + n % 8) : 8;
                std::vector<Ray> rays;
                for (std::size_t i = 0; i < size; ++i) {
                    const Vector3 d =
                        centre + Vector3{float(i % 4) * pixel, float(i / 4) * pixel, 0};
                    rays.push_back({eye, normalize(d)});
                }
                if (n % 10 == 9) rays[std::size_t(n) % size].direction.y = nan;
                const Interval range = n % 5 == 4 ? Interval{0, 30} : Interval{};
                agree.check_packet(rays, range, "packet " + std::to_string(n));
                if (HasFatalFailure()) break;
            }
            EXPECT_GT(agree.packet_hits(), packets * 4) << simd_path_name(path);
            EXPECT_GT(agree.packet_blocked(), packets * 4) << simd_path_name(path);
        }
    }
    set_simd_path(saved);
}

TEST(AggregateProperties, NanAndZeroLengthDirectionsHitNothingOrAgree) {
    const auto prims = random_mix(500, 8);
    Agreement agree(prims);
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const Point3 origins[] = {{0, 0, 0}, {30, 30, 30}, {3, -2, 1}};
    for (const Point3 o : origins) {
        for (const Vector3 d : {Vector3{nan, nan, nan}, Vector3{nan, 0, 1}, Vector3{0, 0, 0},
                                Vector3{-0.0f, 0.0f, -0.0f}}) {
            const Ray ray{o, d};
            agree.check(ray, {}, ray_text(ray, 0));
            agree.check(ray, {0, 5}, ray_text(ray, 0) + " short");
            const bool is_nan = std::isnan(d.x) || std::isnan(d.y);
            for (const std::string_view name : accel_names()) {
                if (name == "embree" && !is_nan) continue;
                const auto aggregate = make_aggregate(*accel_from_name(name), prims);
                // NaN hits nothing; a zero direction from outside every primitive neither.
                // (From inside a sphere or box the shapes themselves report a hit at some
                // t > 0 for a zero direction; the list does too, and the check above holds.)
                if (is_nan || o.x == 30) {
                    EXPECT_FALSE(aggregate->intersect(ray, {}, ~0u)) << name;
                }
            }
        }
    }
    // A NaN origin, and a NaN interval.
    agree.check({{nan, 0, 0}, {0, 0, 1}}, {}, "NaN origin");
    agree.check({{0, 0, -20}, {0, 0, 1}}, {nan, 10}, "NaN interval");
}

TEST(AggregateProperties, BuildsOverNoneOneAndOnlyUnboundedPrimitives) {
    const Ray down{{0.5f, 5, 0.25f}, {0, -1, 0}};
    const std::vector<std::vector<Primitive>> scenes{
        {},
        {{Sphere{{0, 0, 0}, 1}}},
        {{Triangle{{Point3{0, 0, 0}, Point3{1, 0, 0}, Point3{0, 0, 1}}}}},
        {{Plane{}}, {Plane{{0, 1, 0}, {0, 1, 0}}, kVisibleToShadowRays}},
    };
    for (const auto& prims : scenes) {
        Agreement agree(prims);
        agree.check(down, {}, "down");
        agree.check({{0, 0, -5}, {0, 0, 1}}, {}, "along z");
        agree.check({{0, -3, 0}, {0, 1, 0}}, {0, 2.5f}, "up, short");
    }
    for (const std::string_view name : accel_names()) {
        const std::vector<Primitive> none;
        EXPECT_TRUE(make_aggregate(*accel_from_name(name), none)->bounds().is_empty()) << name;
    }
}

// A hundred thousand under a sanitizer, as the BVH tests' coincident boxes.
TEST(AggregateProperties, AMillionCoincidentSpheres) {
    const std::vector<Primitive> prims(testing::kUnderSanitizer ? 100'000 : 1'000'000,
                                       Primitive{Sphere{{1, 2, 3}, 0.5f}});
    Agreement agree(prims);
    const Ray rays[] = {{{1, 2, -10}, {0, 0, 1}},
                        {{1, 2, 3}, {0, 1, 0}},
                        {{-5, -5, -5}, normalize(Vector3{6, 7, 8})},
                        {{1.5f, 2, -10}, {0, 0, 1}},  // grazing
                        {{5, 5, 5}, {1, 0, 0}}};      // away
    for (const Ray& ray : rays) agree.check(ray, {}, ray_text(ray, 0));
    EXPECT_EQ(agree.list().intersect(rays[0], {}, ~0u)->primitive, 0u);
    EXPECT_GE(agree.hits(), 6);
}

}  // namespace
}  // namespace glint
