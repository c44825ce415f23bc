// CSG against brute-force point membership: along random rays, the first hit of a CSG shape must
// be where membership in the result first changes, and its normal must point out of the result.
#include "glint/geometry/csg.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>
#include <vector>

#include "glint/geometry/shape.h"
#include "shape_property_checks.h"

namespace glint {
namespace {

using Membership = std::function<bool(Point3)>;

struct Solid {
    std::shared_ptr<const Shape> shape;
    Membership inside;
};

Solid sphere(Point3 c, float r) {
    return {std::make_shared<const Shape>(Sphere{c, r}),
            [=](Point3 p) { return distance(p, c) < r; }};
}

Solid box(Point3 lo, Point3 hi) {
    return {std::make_shared<const Shape>(Box{lo, hi}), [=](Point3 p) {
                return p.x > lo.x && p.x < hi.x && p.y > lo.y && p.y < hi.y && p.z > lo.z &&
                       p.z < hi.z;
            }};
}

Solid combine(CsgOperation op, const Solid& a, const Solid& b) {
    Membership inside;
    switch (op) {
        case CsgOperation::union_of:
        case CsgOperation::merge:
            inside = [=](Point3 p) { return a.inside(p) || b.inside(p); };
            break;
        case CsgOperation::intersection:
        case CsgOperation::clip:  // its surface is a's inside b (clip tests check it themselves)
            inside = [=](Point3 p) { return a.inside(p) && b.inside(p); };
            break;
        case CsgOperation::difference:
            inside = [=](Point3 p) { return a.inside(p) && !b.inside(p); };
            break;
    }
    return {std::make_shared<const Shape>(Csg{op, a.shape, b.shape}), inside};
}

// The first change of membership along the ray, found by fine marching over the part of the ray
// inside the solid's bounds (outside them nothing is inside).
std::optional<float> first_change(const Solid& solid, const Ray& ray, float t_max) {
    constexpr float kStep = 1e-3f;
    const bool start = solid.inside(ray.origin);
    const Bounds3 box = bounds(*solid.shape);
    float t0 = kStep, t1 = t_max;
    if (box.is_finite()) {
        const auto clipped = intersect_slabs(box, ray, {0, t_max});
        if (!clipped) return std::nullopt;
        t0 = std::max(kStep, clipped->min - kStep);
        t1 = std::min(t_max, clipped->max + kStep);
    }
    for (float t = t0; t < t1; t += kStep)
        if (solid.inside(ray.at(t)) != start) return t;
    return std::nullopt;
}

struct MembershipOptions {
    int rays = 400;
    float t_tolerance = 2e-3f;
    // Rays whose first hit may disagree with the first change of membership (in being there or
    // in t): 0 for analytic operands. A fractal's solid ends in a shell of the distance estimate,
    // which rays grazing it cross where the marching samples do not.
    float disagreeing_fraction = 0;
    // How far the normal is probed on both sides; 0 skips it, for surfaces rough at that scale.
    float normal_probe = 1e-3f;
};

// `line` is the caller's: std::source_location is not there with clang 14 and libstdc++.
void expect_matches_membership(const Solid& solid, const MembershipOptions& options = {},
                               const int line = __builtin_LINE()) {
    SCOPED_TRACE(::testing::Message() << "case at line " << line);
    testing::RandomRays rays({0, 0, 0}, 1.6f, 7);
    int hits = 0, normal_misses = 0, facing_away = 0, disagreeing = 0;
    for (int i = 0; i < options.rays; ++i) {
        const Ray ray = rays.next();
        const auto hit = intersect(*solid.shape, ray, {});
        const auto change = first_change(solid, ray, 14);
        if (hit.has_value() != change.has_value() ||
            (hit && std::abs(hit->t - *change) > options.t_tolerance)) {
            ++disagreeing;
            if (options.disagreeing_fraction == 0) {
                ADD_FAILURE() << "ray " << i << ": hit " << (hit ? hit->t : -1) << ", membership "
                              << "changes at " << (change ? *change : -1);
            }
            continue;
        }
        if (!hit) continue;
        ++hits;
        // The normal points out of the result: against the ray, which enters the result at its
        // first hit; and outside just beyond it, inside just before. Hits within the probe
        // distance of an edge, where the operands meet, may see the other operand on one side;
        // they are few.
        const SurfacePoint sp = surface_at(*solid.shape, ray, *hit);
        if (dot(sp.normal, ray.direction) >= 0) ++facing_away;
        const Vector3 probe = to_vector(sp.normal) * options.normal_probe;
        if (options.normal_probe > 0 && (solid.inside(sp.p + probe) || !solid.inside(sp.p - probe)))
            ++normal_misses;
    }
    EXPECT_LE(disagreeing, options.disagreeing_fraction * float(options.rays));
    EXPECT_LE(facing_away, hits / 50) << "normals not pointing out of the result";
    EXPECT_LE(normal_misses, hits / 50) << "normals not pointing out of the result";
    EXPECT_GT(hits, options.rays / 8);
}

const Solid kBall = sphere({0, 0, 0}, 1.2f);
const Solid kCube = box({-1, -1, -1}, {1, 1, 1});

TEST(Csg, MergeIsTheSurfaceOfTheUnion) {
    expect_matches_membership(combine(CsgOperation::merge, kBall, kCube));
}

TEST(Csg, IntersectionIsTheCommonPart) {
    expect_matches_membership(combine(CsgOperation::intersection, kBall, kCube));
}

TEST(Csg, DifferenceCarvesTheSecondOutOfTheFirst) {
    expect_matches_membership(combine(CsgOperation::difference, kCube, kBall));
    expect_matches_membership(combine(CsgOperation::difference, kBall, kCube));
}

// A clip's first hit is a's first hit inside b, found by walking a's hits one by one; its
// normal is a's own.
void expect_clip_matches_brute_force(const Solid& a, const Solid& b) {
    const Shape clip = Csg{CsgOperation::clip, a.shape, b.shape};
    testing::RandomRays rays({0, 0, 0}, 1.6f, 11);
    int hits = 0;
    for (int i = 0; i < 400; ++i) {
        const Ray ray = rays.next();
        std::optional<ShapeHit> expected;
        for (float t_min = 0;;) {
            const auto h = intersect(*a.shape, ray, {t_min, kInfinity});
            if (!h) break;
            if (b.inside(ray.at(h->t))) {
                expected = h;
                break;
            }
            t_min = std::nextafter(h->t, kInfinity);
        }
        const auto hit = intersect(clip, ray, {});
        ASSERT_EQ(hit.has_value(), expected.has_value()) << "ray " << i;
        if (!hit) continue;
        ++hits;
        EXPECT_NEAR(hit->t, expected->t, 1e-5f) << "ray " << i;
        const Normal3 n = surface_at(clip, ray, *hit).normal;
        const Normal3 n_a = surface_at(*a.shape, ray, *expected).normal;
        EXPECT_NEAR(dot(n, n_a), 1, 1e-5f) << "ray " << i;
    }
    EXPECT_GT(hits, 40);
}

TEST(Csg, ClipKeepsTheFirstSurfaceInsideTheSecondAndNothingOfIt) {
    // A sphere cut open by a box (a bowl whose inside rays reach), a box by a sphere, and an
    // open surface (a disk) by a half-space.
    expect_clip_matches_brute_force(sphere({0, 0, 0}, 1), box({-2, -2, -2}, {2, 0.3f, 2}));
    expect_clip_matches_brute_force(box({-0.8f, -0.8f, -0.8f}, {0.8f, 0.8f, 0.8f}),
                                    sphere({0, 0, 0}, 1));
    const Solid disk{std::make_shared<const Shape>(Disk{{0, 0, 0}, {0, 1, 0}, 1.2f}),
                     [](Point3) { return false; }};
    const Solid below{std::make_shared<const Shape>(Plane{{0.3f, 0, 0}, {1, 0, 0}}),
                      [](Point3 p) { return p.x < 0.3f; }};
    expect_clip_matches_brute_force(disk, below);
    // Its bounds are its operands' common part.
    const Shape clip =
        Csg{CsgOperation::clip, sphere({0, 0, 0}, 1).shape, box({-2, -2, -2}, {2, 0.3f, 2}).shape};
    EXPECT_EQ(bounds(clip).max.y, 0.3f);
    EXPECT_EQ(bounds(clip).min.y, -1);
}

TEST(Csg, NestedOperationsToSeveralLevels) {
    // A cube with the ball's middle removed, minus a slab, merged with a small sphere.
    const Solid carved = combine(CsgOperation::difference, kCube, sphere({0, 0, 0}, 0.7f));
    const Solid cut = combine(CsgOperation::difference, carved, box({-2, -0.2f, -2}, {2, 0.2f, 2}));
    const Solid nested = combine(CsgOperation::merge, cut, sphere({0.8f, 0.8f, 0.8f}, 0.5f));
    expect_matches_membership(nested);
    EXPECT_EQ(csg_depth(*nested.shape), 3);
}

// Each operand may show its own material: the hit names the innermost operand that has one, through
// transforms and nested levels; elsewhere the object's own (0).
TEST(Csg, HitsNameTheMaterialOfTheOperandTheyLieOn) {
    // (cube with material 3, minus a ball with none), moved, merged with a sphere of material 5.
    Csg carved{CsgOperation::difference, kCube.shape, sphere({0, 0, -1}, 0.6f).shape};
    carved.material_a = 3;
    const auto moved = std::make_shared<const Shape>(
        Transformed(Transform::translate({0, 0, 2}), std::make_shared<const Shape>(carved)));
    Csg whole{CsgOperation::union_of, moved, sphere({0, 3, 2}, 0.5f).shape};
    whole.material_b = 5;
    whole.material_a = 7;  // the carved cube's, where its own operands have none
    const Shape shape = whole;
    EXPECT_TRUE(has_operand_materials(shape));
    EXPECT_FALSE(has_operand_materials(*kCube.shape));
    const auto material_along = [&](Point3 from, Vector3 d) {
        const auto hit = intersect(shape, Ray{from, d}, {0, kInfinity});
        EXPECT_TRUE(hit.has_value());
        return hit ? operand_material(shape, *hit) : 0;
    };
    EXPECT_EQ(material_along({0.5f, 0.5f, -5}, {0, 0, 1}), 3u);  // the cube's front
    EXPECT_EQ(material_along({0, 0, -5}, {0, 0, 1}), 7u);        // the ball's cut: the level above
    EXPECT_EQ(material_along({0, 3, -5}, {0, 0, 1}), 5u);        // the sphere
    Csg plain{CsgOperation::union_of, kCube.shape, kBall.shape};
    EXPECT_FALSE(has_operand_materials(Shape{plain}));
}

// A closed mesh is a solid: an octahedron |x| + |y| + |z| < r of 8 triangles, wound outwards.
Solid octahedron(float r) {
    MeshData arrays;
    arrays.positions = {{r, 0, 0}, {-r, 0, 0}, {0, r, 0}, {0, -r, 0}, {0, 0, r}, {0, 0, -r}};
    arrays.triangles = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4},
                        {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
    const MeshBuild built = build_mesh(std::move(arrays));
    EXPECT_TRUE(built.mesh && is_closed_surface(*built.mesh)) << built.error;
    return {std::make_shared<const Shape>(TriangleMesh{built.mesh}),
            [=](Point3 p) { return std::abs(p.x) + std::abs(p.y) + std::abs(p.z) < r; }};
}

TEST(Csg, ClosedMeshesAreOperandsToo) {
    const Solid octa = octahedron(1.5f);
    EXPECT_TRUE(is_solid(*octa.shape));
    expect_matches_membership(combine(CsgOperation::intersection, octa, kCube));
    expect_matches_membership(combine(CsgOperation::difference, kBall, octa));
}

// The YAML loader nests lists of operands as little as it can: a difference of [a, b, c] as
// a - (b merge c). Both give the same hits and normals as (a - b) - c.
TEST(Csg, DifferenceOfAMergeIsTheSameAsDifferencesInTurn) {
    const Solid b = sphere({0.6f, 0.3f, 0}, 0.7f),
                c = box({-1.5f, -0.2f, -0.4f}, {0.2f, 0.3f, 0.4f});
    const Shape in_turn =
        Csg{CsgOperation::difference,
            std::make_shared<const Shape>(Csg{CsgOperation::difference, kCube.shape, b.shape}),
            c.shape};
    const Shape at_once =
        Csg{CsgOperation::difference, kCube.shape,
            std::make_shared<const Shape>(Csg{CsgOperation::merge, b.shape, c.shape})};
    testing::RandomRays rays({0, 0, 0}, 1.6f, 3);
    int hits = 0;
    for (int i = 0; i < 1000; ++i) {
        const Ray ray = rays.next();
        const auto h1 = intersect(in_turn, ray, {});
        const auto h2 = intersect(at_once, ray, {});
        ASSERT_EQ(h1.has_value(), h2.has_value()) << "ray " << i;
        if (!h1) continue;
        ++hits;
        EXPECT_EQ(h1->t, h2->t) << "ray " << i;
        EXPECT_EQ(surface_at(in_turn, ray, *h1).normal, surface_at(at_once, ray, *h2).normal);
    }
    EXPECT_GT(hits, 300);
}

TEST(Csg, UnionKeepsInternalSurfaces) {
    // POV-Ray's union: the first surface of either operand, inside the other or not.
    const Solid u = combine(CsgOperation::union_of, kBall, kCube);
    const Ray from_centre{{0, 0, 0}, {1, 0, 0}};
    const auto hit = intersect(*u.shape, from_centre, {});
    ASSERT_TRUE(hit);
    EXPECT_FLOAT_EQ(hit->t, 1);  // the cube's face, inside the ball
    const Solid m = combine(CsgOperation::merge, kBall, kCube);
    EXPECT_FLOAT_EQ(intersect(*m.shape, from_centre, {})->t, 1.2f);  // merge: only the ball
}

TEST(Csg, HalfSpaceOperandCutsASphereInHalf) {
    // A plane is a half-space (inside below its normal): the lower half of a ball.
    const Solid lower = {std::make_shared<const Shape>(Plane{{0, 0, 0}, {0, 1, 0}}),
                         [](Point3 p) { return p.y < 0; }};
    expect_matches_membership(combine(CsgOperation::intersection, kBall, lower));
    // A ray parallel to the plane, below it, sees the ball; above it, nothing.
    const Csg half{CsgOperation::intersection, kBall.shape, lower.shape};
    EXPECT_TRUE(half.intersect({{-5, -0.5f, 0}, {1, 0, 0}}, {}));
    EXPECT_FALSE(half.intersect({{-5, 0.5f, 0}, {1, 0, 0}}, {}));
}

TEST(Csg, BoundsFollowTheOperation) {
    const Csg difference{CsgOperation::difference, kCube.shape, kBall.shape};
    EXPECT_EQ(difference.bounds().max, (Point3{1, 1, 1}));
    const Csg intersection{CsgOperation::intersection, kCube.shape,
                           std::make_shared<const Shape>(Sphere{{1, 0, 0}, 0.5f})};
    EXPECT_EQ(intersection.bounds().min, (Point3{0.5f, -0.5f, -0.5f}));
}

TEST(Csg, OnlyClosedShapesAreSolids) {
    EXPECT_TRUE(is_solid(Shape{Sphere{}}));
    EXPECT_TRUE(is_solid(Shape{Csg{CsgOperation::merge, kBall.shape, kCube.shape}}));
    EXPECT_FALSE(is_solid(Shape{Triangle{}}));
    EXPECT_FALSE(
        is_solid(Shape{Transformed{Transform{}, std::make_shared<const Shape>(Triangle{})}}));
}

// The axial coordinates of p about the segment from `base` to `top`: height along it from base,
// and distance from its line.
struct Axial {
    float height, rho, length;
};
Axial axial(Point3 p, Point3 base, Point3 top) {
    const Vector3 axis = normalize(top - base);
    const float height = dot(p - base, axis);
    return {height, length((p - base) - axis * height), length(top - base)};
}

Solid capped_cylinder(Point3 base, Point3 top, float r) {
    return {std::make_shared<const Shape>(Cylinder{base, top, r, true}), [=](Point3 p) {
                const Axial a = axial(p, base, top);
                return a.height > 0 && a.height < a.length && a.rho < r;
            }};
}

Solid capped_cone(Point3 base, float base_radius, Point3 apex, float apex_radius) {
    return {std::make_shared<const Shape>(Cone{base, base_radius, apex, apex_radius, true}),
            [=](Point3 p) {
                const Axial a = axial(p, base, apex);
                const float radius =
                    base_radius + (apex_radius - base_radius) * a.height / a.length;
                return a.height > 0 && a.height < a.length && a.rho < radius;
            }};
}

// About the y axis through the origin.
Solid torus(float major, float minor) {
    return {std::make_shared<const Shape>(Torus{{0, 0, 0}, {0, 1, 0}, major, minor}),
            [=](Point3 p) { return std::hypot(std::hypot(p.x, p.z) - major, p.y) < minor; }};
}

// A rounded cube, x^4 + y^4 + z^4 < r^4, in a region that encloses it.
Solid superellipsoid(float r) {
    auto compiled = compile_expression("x^4 + y^4 + z^4 - r^4", {{"r", r}});
    EXPECT_TRUE(std::holds_alternative<Expression>(compiled));
    ImplicitSurface surface;
    surface.f = std::make_shared<const Expression>(std::get<Expression>(std::move(compiled)));
    const float half = 1.2f * r;
    surface.region = {{-half, -half, -half}, {half, half, half}};
    return {std::make_shared<const Shape>(surface), [=](Point3 p) {
                return p.x * p.x * p.x * p.x + p.y * p.y * p.y * p.y + p.z * p.z * p.z * p.z <
                       r * r * r * r;
            }};
}

Solid transformed(const Transform& world_from_object, const Solid& solid) {
    const Transform object_from_world = world_from_object.inverse();
    return {std::make_shared<const Shape>(Transformed{world_from_object, solid.shape}),
            [=](Point3 p) { return solid.inside(object_from_world(p)); }};
}

Solid half_space(Point3 point, Vector3 normal) {
    const Normal3 n(normalize(normal));
    return {std::make_shared<const Shape>(Plane{point, n}),
            [=](Point3 p) { return dot(n, p - point) < 0; }};
}

// The operands joined by op in a balanced tree, as the scene loader joins a list.
Solid balanced(CsgOperation op, const std::vector<Solid>& operands, std::size_t begin,
               std::size_t end) {
    if (end - begin == 1) return operands[begin];
    const std::size_t middle = begin + (end - begin) / 2;
    return combine(op, balanced(op, operands, begin, middle), balanced(op, operands, middle, end));
}
Solid balanced(CsgOperation op, const std::vector<Solid>& operands) {
    return balanced(op, operands, 0, operands.size());
}

// The notes' convex polyhedra, "intersect planes only": a cube of six half-spaces.
std::vector<Solid> cube_faces() {
    return {half_space({1, 0, 0}, {1, 0, 0}), half_space({-1, 0, 0}, {-1, 0, 0}),
            half_space({0, 1, 0}, {0, 1, 0}), half_space({0, -1, 0}, {0, -1, 0}),
            half_space({0, 0, 1}, {0, 0, 1}), half_space({0, 0, -1}, {0, 0, -1})};
}

// Rays along z and along x over a grid, parallel to four of the cube's faces: they never cross
// those, and where they pass inside them those operands must count as inside all along.
void expect_axis_rays_match_membership(const Solid& solid, const int line = __builtin_LINE()) {
    SCOPED_TRACE(::testing::Message() << "case at line " << line);
    int disagreeing = 0;
    for (int i = 0; i <= 20; ++i)
        for (int j = 0; j <= 20; ++j) {
            const float a = -1.55f + 0.155f * float(i), b = -1.55f + 0.155f * float(j);
            for (const Ray& ray : {Ray{{a, b, -5}, {0, 0, 1}}, Ray{{-5, a, b}, {1, 0, 0}}}) {
                const auto hit = intersect(*solid.shape, ray, {});
                const auto change = first_change(solid, ray, 14);
                if (hit.has_value() != change.has_value() ||
                    (hit && std::abs(hit->t - *change) > 2e-3f))
                    ++disagreeing;
            }
        }
    EXPECT_EQ(disagreeing, 0);
}

TEST(Csg, OperandsARayNeverCrossesKeepTheirSide) {
    const Solid cube = balanced(CsgOperation::intersection, cube_faces());
    expect_matches_membership(cube);
    expect_axis_rays_match_membership(cube);
    // A cube of placed half-spaces: each face a plane through the origin, moved out along its
    // normal.
    std::vector<Solid> placed;
    for (const Solid& face : cube_faces()) {
        const Normal3 n = std::get<Plane>(*face.shape).normal;
        placed.push_back(
            transformed(Transform::translate(to_vector(n)), half_space({0, 0, 0}, to_vector(n))));
    }
    expect_axis_rays_match_membership(balanced(CsgOperation::intersection, placed));
    // Every operation with a slab (two faces, a CSG shape of its own) as an operand: the ball
    // cut by it, the ball merged with it, the slab minus the ball, and the cube minus a slab.
    const Solid slab = combine(CsgOperation::intersection, cube_faces()[0], cube_faces()[1]);
    // (A union keeps internal surfaces, where membership does not change: not compared.)
    for (const CsgOperation op :
         {CsgOperation::intersection, CsgOperation::merge, CsgOperation::difference}) {
        expect_axis_rays_match_membership(combine(op, kBall, slab));
        expect_axis_rays_match_membership(combine(op, slab, kBall));
    }
    const Solid thin_slab = combine(CsgOperation::intersection, half_space({0, 0.3f, 0}, {0, 1, 0}),
                                    half_space({0, -0.3f, 0}, {0, -1, 0}));
    expect_axis_rays_match_membership(combine(CsgOperation::difference, cube, thin_slab));
    expect_matches_membership(combine(CsgOperation::difference, cube, thin_slab));
}

TEST(Csg, CappedCylindersAndConesAreOperands) {
    const Solid rod = capped_cylinder({-0.3f, -1.5f, 0.2f}, {0.4f, 1.4f, -0.1f}, 0.45f);
    EXPECT_TRUE(is_solid(*rod.shape));
    expect_matches_membership(combine(CsgOperation::difference, kCube, rod));
    expect_matches_membership(combine(CsgOperation::merge, kBall, rod));
    const Solid frustum = capped_cone({0.1f, -1.3f, 0}, 1.1f, {-0.2f, 1.2f, 0.3f}, 0.4f);
    const Solid spike = capped_cone({0, -0.2f, -1.5f}, 0.5f, {0.1f, 0.3f, 1.5f}, 0);
    expect_matches_membership(combine(CsgOperation::intersection, frustum, kCube));
    expect_matches_membership(combine(CsgOperation::difference, kBall, spike));
}

TEST(Csg, ToriAreOperands) {
    const Solid ring = torus(1, 0.35f);
    expect_matches_membership(combine(CsgOperation::difference, ring, kCube));
    expect_matches_membership(
        combine(CsgOperation::intersection, ring, box({-2, -2, -2}, {2, 2, 0.3f})));
    expect_matches_membership(combine(CsgOperation::merge, ring, sphere({0, 0, 0}, 0.8f)));
}

TEST(Csg, ImplicitSurfacesAreOperands) {
    const Solid rounded = superellipsoid(1.1f);
    EXPECT_TRUE(is_solid(*rounded.shape));
    expect_matches_membership(combine(CsgOperation::difference, rounded, kBall));
    expect_matches_membership(
        combine(CsgOperation::intersection, rounded, sphere({0.5f, 0, 0}, 1)));
}

// An implicit surface is a solid when its box encloses it, not when the box cuts it open.
TEST(Csg, ImplicitSurfacesCutOpenByTheirBoxAreNotSolids) {
    const Solid rounded = superellipsoid(1);
    EXPECT_TRUE(is_solid(*rounded.shape));
    ImplicitSurface cut = std::get<ImplicitSurface>(*rounded.shape);
    cut.region.max.x = 0.5f;
    EXPECT_FALSE(is_solid(Shape{cut}));
    EXPECT_FALSE(is_solid(Shape{Transformed{Transform{}, std::make_shared<const Shape>(cut)}}));
}

TEST(Csg, TransformedShapesAreOperands) {
    // Non-uniformly scaled, turned and moved: the ball becomes a tilted ellipsoid, the cube a
    // slanted brick, and the torus an oval ring.
    const Transform squash = Transform::translate({0.2f, -0.1f, 0}) *
                             Transform::rotate({1, 1, 0}, 35) * Transform::scale(1.3f, 0.6f, 0.9f);
    const Solid ellipsoid = transformed(squash, kBall);
    const Solid brick =
        transformed(Transform::rotate({0, 0, 1}, 30) * Transform::scale(1.4f, 0.5f, 0.8f), kCube);
    expect_matches_membership(combine(CsgOperation::difference, brick, ellipsoid));
    expect_matches_membership(combine(CsgOperation::intersection, ellipsoid, kCube));
    expect_matches_membership(
        combine(CsgOperation::merge, transformed(squash, torus(1, 0.3f)), sphere({0, 0, 0}, 0.5f)));
    // A CSG shape placed as a whole.
    const Solid carved = combine(CsgOperation::difference, kCube, kBall);
    expect_matches_membership(transformed(squash, carved));
}

// Quaternion Julia sets and the Mandelbulb are solids: inside is where their distance estimate is
// below epsilon, and a ray that starts inside finds where it leaves.
Solid fractal(const JuliaSet& julia) {
    return {std::make_shared<const Shape>(julia), [=](Point3 p) { return julia.inside(p); }};
}
Solid fractal(const Mandelbulb& bulb) {
    return {std::make_shared<const Shape>(bulb), [=](Point3 p) { return bulb.inside(p); }};
}

// With c = 0 the Julia set is the unit ball (julia_set_test.cpp), so as an operand it must carve
// and cut a cube as the analytic ball does: the same hits, up to its epsilon shell, on all rays
// but a few grazing ones; and the same normals.
TEST(Csg, JuliaSetWithZeroConstantCutsAsTheEqualBall) {
    const JuliaSet julia;
    const auto ball = std::make_shared<const Shape>(Sphere{{0, 0, 0}, 1});
    const auto set = std::make_shared<const Shape>(julia);
    const auto cube = std::make_shared<const Shape>(Box{{-0.8f, -0.8f, -0.8f}, {0.8f, 0.8f, 0.8f}});
    for (const CsgOperation op : {CsgOperation::difference, CsgOperation::intersection}) {
        SCOPED_TRACE(op == CsgOperation::difference ? "difference" : "intersection");
        const Shape with_set = Csg{op, cube, set}, with_ball = Csg{op, cube, ball};
        testing::RandomRays rays({0, 0, 0}, 1.2f, 31);
        constexpr int kRays = 2000;
        int hits = 0, disagreeing = 0;
        for (int i = 0; i < kRays; ++i) {
            const Ray ray = rays.next();
            const auto a = intersect(with_set, ray, {});
            const auto b = intersect(with_ball, ray, {});
            if (a.has_value() != b.has_value() || (a && std::abs(a->t - b->t) > 0.01f)) {
                ++disagreeing;
                continue;
            }
            if (!a) continue;
            ++hits;
            // Near the circles where the cube meets the ball one may hit a face, the other the
            // ball, a shell's width apart.
            if ((a->csg_path ^ b->csg_path) & 1) continue;
            const Normal3 na = surface_at(with_set, ray, *a).normal;
            const Normal3 nb = surface_at(with_ball, ray, *b).normal;
            EXPECT_GT(dot(na, nb), 0.99f) << "ray " << i;
        }
        EXPECT_GT(hits, kRays / 3);
        EXPECT_LE(disagreeing, kRays / 100);
    }
    // Against brute-force membership too.
    MembershipOptions options;
    options.t_tolerance = 5 * julia.epsilon;
    options.disagreeing_fraction = 0.01f;
    expect_matches_membership(combine(CsgOperation::difference, kCube, fractal(julia)), options);
}

// The Mandelbulb carved out of a cube (rays reach its inside through the cube's faces and must
// find where they leave it) and cut by a slab (its inside shows through the slab's faces). The
// rays that disagree (1% here) cross gaps in the bulb narrower than the exit march's step (4e-3
// at 512 steps); raising max_steps resolves them.
TEST(Csg, MandelbulbOperandMatchesMembership) {
    const Mandelbulb bulb;
    MembershipOptions options;
    options.rays = 1000;
    options.t_tolerance = 5 * bulb.epsilon;
    options.disagreeing_fraction = 0.02f;
    options.normal_probe = 0;  // the bulb is rough at the epsilon scale
    expect_matches_membership(
        combine(CsgOperation::difference, box({-0.7f, -0.7f, -0.7f}, {0.7f, 0.7f, 0.7f}),
                fractal(bulb)),
        options);
    expect_matches_membership(
        combine(CsgOperation::intersection, fractal(bulb), box({-2, -0.3f, -2}, {2, 0.3f, 2})),
        options);
}

// Skipping uv reaches the sphere through every shape that holds others: CSG, a placement and a
// motion, nested.
TEST(Csg, WrappersPassOnWhetherUvIsWanted) {
    const auto ball = std::make_shared<const Shape>(Sphere{{0, 0, 0}, 1});
    const auto placed =
        std::make_shared<const Shape>(Transformed{Transform::translate({0, 0, 5}), ball});
    const auto moving = std::make_shared<const Shape>(
        Moving{std::make_shared<const AnimatedTransform>(Transform::scale(2, 2, 2)), placed});
    const Shape shape = Csg{CsgOperation::union_of, moving, ball};
    const Ray ray{{0.5f, 0.5f, 20}, {0, 0, -1}};  // meets the moving sphere, at z = 10, first
    const auto hit = intersect(shape, ray, {});
    ASSERT_TRUE(hit);
    const SurfacePoint with = surface_at(shape, ray, *hit, Uv::compute);
    const SurfacePoint without = surface_at(shape, ray, *hit, Uv::skip);
    EXPECT_NEAR(with.p.z, 10 + std::sqrt(3.5f), 1e-4f);  // 4 = 0.5 + (z - 10)^2
    EXPECT_EQ(without.p, with.p);
    EXPECT_EQ(without.normal, with.normal);
    EXPECT_NE(with.uv, (Point2{0, 0}));
    EXPECT_EQ(without.uv, (Point2{0, 0}));
}

}  // namespace
}  // namespace glint
