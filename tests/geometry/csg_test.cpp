// CSG against brute-force point membership: along random rays, the first hit of a CSG shape must
// be where membership in the result first changes, and its normal must point out of the result.
#include "glint/geometry/csg.h"

#include <gtest/gtest.h>

#include <functional>
#include <memory>

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
            inside = [=](Point3 p) { return a.inside(p) && b.inside(p); };
            break;
        case CsgOperation::difference:
            inside = [=](Point3 p) { return a.inside(p) && !b.inside(p); };
            break;
    }
    return {std::make_shared<const Shape>(Csg{op, a.shape, b.shape}), inside};
}

// The first change of membership along the ray, found by fine marching.
std::optional<float> first_change(const Membership& inside, const Ray& ray, float t_max) {
    constexpr float kStep = 1e-3f;
    const bool start = inside(ray.origin);
    for (float t = kStep; t < t_max; t += kStep)
        if (inside(ray.at(t)) != start) return t;
    return std::nullopt;
}

void expect_matches_membership(const Solid& solid) {
    testing::RandomRays rays({0, 0, 0}, 1.6f, 7);
    int hits = 0, normal_misses = 0;
    for (int i = 0; i < 400; ++i) {
        const Ray ray = rays.next();
        const auto hit = intersect(*solid.shape, ray, {});
        const auto change = first_change(solid.inside, ray, 14);
        ASSERT_EQ(hit.has_value(), change.has_value()) << "ray " << i;
        if (!hit) continue;
        ++hits;
        EXPECT_NEAR(hit->t, *change, 2e-3f) << "ray " << i;
        // The normal points out of the result: outside just beyond it, inside just before.
        // Hits within the probe distance of an edge, where the operands meet, may see the other
        // operand on one side; they are few.
        const SurfacePoint sp = surface_at(*solid.shape, ray, *hit);
        const Vector3 probe = to_vector(sp.normal) * 1e-3f;
        if (solid.inside(sp.p + probe) || !solid.inside(sp.p - probe)) ++normal_misses;
    }
    EXPECT_LE(normal_misses, hits / 50) << "normals not pointing out of the result";
    EXPECT_GT(hits, 50);
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

TEST(Csg, NestedOperationsToSeveralLevels) {
    // A cube with the ball's middle removed, minus a slab, merged with a small sphere.
    const Solid carved = combine(CsgOperation::difference, kCube, sphere({0, 0, 0}, 0.7f));
    const Solid cut = combine(CsgOperation::difference, carved, box({-2, -0.2f, -2}, {2, 0.2f, 2}));
    const Solid nested = combine(CsgOperation::merge, cut, sphere({0.8f, 0.8f, 0.8f}, 0.5f));
    expect_matches_membership(nested);
    EXPECT_EQ(csg_depth(*nested.shape), 3);
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

}  // namespace
}  // namespace glint
