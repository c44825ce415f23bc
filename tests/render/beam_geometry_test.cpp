// Beam tracing's geometry with worked numbers: the mirror and apparent-depth maps, exact pixel
// areas, shadow polygons; and the BSP tree's order against brute force: along any ray from the
// eye, the nearest piece hit comes first.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <random>

#include "glint/render/beam/pixel_coverage.h"
#include "glint/render/beam/polygon_bsp.h"
#include "glint/render/beam/shadow_regions.h"

namespace glint::beam {
namespace {

void expect_near(Vector3d a, Vector3d b) {
    EXPECT_NEAR(a.x, b.x, 1e-12);
    EXPECT_NEAR(a.y, b.y, 1e-12);
    EXPECT_NEAR(a.z, b.z, 1e-12);
}

TEST(BeamMaps, MirrorImageInAPlane) {
    const Affine mirror = mirror_in({{0, 1, 0}, 1});  // y = 1
    expect_near(mirror.apply({1, 2, 3}), {1, 0, 3});
    expect_near(mirror.after(mirror).apply({1, 2, 3}), {1, 2, 3});  // an involution
}

TEST(BeamMaps, ApparentDepthBeyondARefractingPlane) {
    // Looking from z < 2 into glass (n = 1.5) beyond z = 2: a point 3 deep appears 2 deep.
    const PlaneD surface{{0, 0, 1}, 2};
    const Affine seen = scale_across(surface, 1 / 1.5);
    expect_near(seen.apply({1, -1, 5}), {1, -1, 4});
    expect_near(seen.apply({4, 5, 2}), {4, 5, 2});  // the plane stays
    expect_near(seen.inverse().apply({1, -1, 4}), {1, -1, 5});
    expect_near(seen.inverse().apply({0, 0, 4}), scale_across(surface, 1.5).apply({0, 0, 4}));
}

TEST(BeamMaps, PlanesPulledBackThroughAMap) {
    // Points whose mirror image (in y = 1) lies on z = 3 + y... the plane dot(n, x) = d
    // pulled back holds exactly the points mapped onto it.
    const Affine mirror = mirror_in({{0, 1, 0}, 1});
    const PlaneD tilted{{0, -1, 1}, 3};
    const PlaneD back = mirror.pull_back(tilted);
    for (const Vector3d p : {Vector3d{0, 0, 3}, Vector3d{2, 1, 4}, Vector3d{-1, 5, 0}})
        EXPECT_NEAR(back.at(p), tilted.at(mirror.apply(p)), 1e-12);
}

std::vector<double> ring(std::initializer_list<double> xy) { return xy; }

TEST(PixelCoverage, AreaOfATriangleInEachPixel) {
    // x + y <= 2: all of pixel (0, 0), half of (1, 0) and of (0, 1), none of (1, 1).
    const auto t = ring({0, 0, 2, 0, 0, 2});
    EXPECT_NEAR(area_in_pixel(t, 0, 0), 1, 1e-12);
    EXPECT_NEAR(area_in_pixel(t, 1, 0), 0.5, 1e-12);
    EXPECT_NEAR(area_in_pixel(t, 0, 1), 0.5, 1e-12);
    EXPECT_NEAR(area_in_pixel(t, 1, 1), 0, 1e-12);
}

TEST(PixelCoverage, GridAddsUpToTheRegionsAreaWithHolesTakenAway) {
    // A 5 x 4 rectangle from (0.25, 0.125) with a 1 x 1 hole, over a 10 x 10 grid.
    const auto at = [](double x, double y) {
        return IntPoint{ClipperLib::cInt(x * kSubpixel), ClipperLib::cInt(y * kSubpixel)};
    };
    Paths region = {{at(0.25, 0.125), at(5.25, 0.125), at(5.25, 4.125), at(0.25, 4.125)},
                    {at(2, 2), at(2, 3), at(3, 3), at(3, 2)}};  // the hole runs the other way
    CoverageGrid grid(0, 0, 10, 10);
    grid.add(region);
    double total = 0, moment_x = 0;
    grid.drain([&](int, int, double area, double cx, double) {
        total += area;
        moment_x += area * cx;
    });
    EXPECT_NEAR(total, 19, 1e-9);
    EXPECT_NEAR(moment_x / total, (20 * 2.75 - 1 * 2.5) / 19, 1e-9);  // the centroid
    EXPECT_NEAR(grid.area_at(2, 2), 0, 1e-12);                        // drained
}

BeamPolygon square(Vector3d center, Vector3d normal, double half, double scale) {
    BeamPolygon p;
    p.frame = frame_of_plane(center, normal, scale);
    const auto c = [&](double a, double b) {
        return p.frame.local(center + p.frame.u * a + p.frame.v * b);
    };
    p.region = {{c(-half, -half), c(half, -half), c(half, half), c(-half, half)}};
    orient_positive(p.region);
    p.plane = {normal, dot(normal, center)};
    return p;
}

double area_of(const Paths& region, double scale) {
    double a = 0;
    for (const Path& r : region) a += ClipperLib::Area(r);
    return a / (scale * scale);
}

TEST(ShadowRegions, AnOccludersShadowIsItsProjectionFromTheLight) {
    // A 4 x 4 floor, a 1 x 1 square 1 above it, a light 2 above: the shadow is 2 x 2.
    const double scale = 1 << 20;
    const std::vector<BeamPolygon> polygons = {square({0, 0, 0}, {0, 1, 0}, 2, scale),
                                               square({0, 1, 0}, {0, 1, 0}, 0.5, scale)};
    const std::vector<Light> lights = {PointLight{{0, 2, 0}, {1, 1, 1}, {}},
                                       DirectionalLight{{0, -1, 0}, {1, 1, 1}}};
    const auto reach = light_reach(lights, polygons, 1e-6);
    ASSERT_FALSE(reach[0][0].everywhere);
    EXPECT_NEAR(area_of(reach[0][0].lit, scale), 16 - 4, 1e-4);
    EXPECT_NEAR(area_of(reach[1][0].lit, scale), 16 - 1, 1e-4);  // parallel light: 1 x 1
    EXPECT_TRUE(reach[0][1].everywhere);                         // nothing above the occluder
}

// Whether the point (in the polygon's plane) lies in the region, away from its edges; nothing
// when it is too near an edge to say.
std::optional<bool> contains(const BeamPolygon& polygon, const Paths& region, Vector3d p) {
    const IntPoint q = polygon.frame.local(p);
    int winding = 0;
    for (const Path& r : region) {
        const int in = ClipperLib::PointInPolygon(q, r);
        if (in < 0) return std::nullopt;
        if (in) winding += ClipperLib::Orientation(r) ? 1 : -1;
    }
    return winding > 0;
}

TEST(PolygonBsp, NearestPieceAlongAnyRayComesFirst) {
    std::mt19937 random(7);
    std::uniform_real_distribution<double> coord(-2, 2), unit(-1, 1);
    const double scale = 1 << 24;
    std::vector<BeamPolygon> triangles;
    for (int i = 0; i < 40; ++i) {
        const Vector3d a{coord(random), coord(random), coord(random)};
        const Vector3d b = a + Vector3d{unit(random), unit(random), unit(random)};
        const Vector3d c = a + Vector3d{unit(random), unit(random), unit(random)};
        Vector3d n = cross(b - a, c - a);
        n = n * (1 / std::sqrt(dot(n, n)));
        BeamPolygon t;
        t.frame = frame_of_plane(a, n, scale);
        t.region = {{t.frame.local(a), t.frame.local(b), t.frame.local(c)}};
        orient_positive(t.region);
        t.plane = {n, dot(n, a)};
        triangles.push_back(t);
    }
    const PolygonBsp bsp(triangles, 1e-7);
    EXPECT_GE(bsp.piece_count(), triangles.size());  // intersecting ones were split
    int checked = 0;
    for (int e = 0; e < 10; ++e) {
        const Vector3d eye{3 * unit(random), 3 * unit(random), 3 * unit(random)};
        std::vector<const BspPiece*> order;
        bsp.front_to_back(eye, [&](const BspPiece& p) {
            order.push_back(&p);
            return true;
        });
        ASSERT_EQ(order.size(), bsp.piece_count());
        for (int r = 0; r < 300; ++r) {
            // Towards a point of a random triangle, so that most rays meet some.
            const BeamPolygon& aim = triangles[random() % triangles.size()];
            const Path& corners = aim.region[0];
            double w[3] = {unit(random) + 1, unit(random) + 1, unit(random) + 1};
            const double sum = w[0] + w[1] + w[2];
            Vector3d target;
            for (int k = 0; k < 3; ++k)
                target = target + aim.frame.world(corners[std::size_t(k)]) * (w[k] / sum);
            const Vector3d d = target - eye;
            // Every piece the ray hits, by distance; the nearest must come first in the order.
            std::vector<std::pair<double, std::size_t>> hits;
            bool unsure = false;
            for (std::size_t k = 0; k < order.size() && !unsure; ++k) {
                const BeamPolygon& t = triangles[order[k]->polygon];
                const double facing = dot(t.plane.n, d);
                if (facing == 0) continue;
                const double s = -t.plane.at(eye) / facing;
                if (s <= 0) continue;
                const auto in = contains(t, order[k]->region, eye + d * s);
                if (!in)
                    unsure = true;
                else if (*in)
                    hits.push_back({s, k});
            }
            if (unsure || hits.size() < 2) continue;
            const auto nearest = *std::min_element(hits.begin(), hits.end());
            const auto first = *std::min_element(
                hits.begin(), hits.end(), [](auto a, auto b) { return a.second < b.second; });
            EXPECT_EQ(nearest.second, first.second) << "eye " << e << ", ray " << r;
            ++checked;
        }
    }
    EXPECT_GT(checked, 500);  // rays that met two pieces or more
}

}  // namespace
}  // namespace glint::beam
