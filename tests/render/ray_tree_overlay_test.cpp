// The ray tree drawn over the image: worked projections through a known camera, the eye ray of a
// pinhole landing on the sample's own film position, segments cut at the eye, feelers marked.
#include "glint/render/explain/ray_tree_overlay.h"

#include <gtest/gtest.h>

#include <string>

#include "glint/render/explain/explain.h"
#include "glint/render/world.h"
#include "glint/scene/load_scene.h"

namespace glint {
namespace {

// Looking down +z from the origin, 90 degrees high, on a 200 x 100 image: the window at
// distance 1 is 4 wide (aspect 2) and 2 high, and right is -x (forward x up).
CameraSpec straight_camera() {
    CameraSpec spec;
    spec.from = {0, 0, 0};
    spec.at = {0, 0, 1};
    spec.up = {0, 1, 0};
    spec.fov = 90;
    return spec;
}

RayTree one_ray(Point3 origin, Vector3 direction, StopReason stop, Point3 hit = {}) {
    RayTree tree;
    RayNode& node = tree.nodes.emplace_back();
    node.ray = Ray{origin, direction};
    node.stop = stop;
    node.point = hit;
    return tree;
}

TEST(RayTreeOverlay, APointProjectsThroughThePinholeAsTheWorkedNumbersSay) {
    // (1, 0.5, 2): 1 to the left of the view over a window half 2 wide at distance 2 is a
    // quarter of the half-width left of the centre, x = (1 - 1/4) 100 = 75; 0.5 up over a
    // half-height of 2 is a quarter up, y = (1 - 1/4) 50 = 37.5.
    const RayTree tree = one_ray({1, 0.5f, 2}, {0, 0, 1}, StopReason::none, /*hit=*/{-2, -1, 4});
    const auto segments = ray_tree_overlay(tree, straight_camera(), 200, 100, 100);
    ASSERT_EQ(segments.size(), 1u);
    EXPECT_NEAR(segments[0].from.x, 75, 1e-4);
    EXPECT_NEAR(segments[0].from.y, 37.5, 1e-4);
    // (-2, -1, 4): a quarter of the half-width right, a quarter of the half-height down.
    EXPECT_NEAR(segments[0].to.x, 125, 1e-4);
    EXPECT_NEAR(segments[0].to.y, 62.5, 1e-4);
    EXPECT_FALSE(segments[0].missed);
}

TEST(RayTreeOverlay, ASegmentIsCutWhereItPassesBehindTheEye) {
    // From in front of the eye to behind it: the part in front stays, its far end cut off.
    const RayTree back = one_ray({1, 0.5f, 2}, {0, 0, -1}, StopReason::missed);
    const auto segments = ray_tree_overlay(back, straight_camera(), 200, 100, 10);
    ASSERT_EQ(segments.size(), 1u);
    EXPECT_TRUE(segments[0].missed);
    EXPECT_NEAR(segments[0].from.x, 75, 1e-4);
    // Near the eye the point runs off far to the left and up, towards the direction (1, 0.5, 0).
    EXPECT_LT(segments[0].to.x, -1e3);
    EXPECT_LT(segments[0].to.y, -1e3);
    EXPECT_NEAR((segments[0].to.y - 50) / (segments[0].to.x - 100), 0.5, 1e-3);
    // Wholly behind: nothing drawn.
    const RayTree behind = one_ray({0, 0, -1}, {0, 0, -1}, StopReason::missed);
    EXPECT_TRUE(ray_tree_overlay(behind, straight_camera(), 200, 100, 10).empty());
}

TEST(RayTreeOverlay, OnlyAStillPerspectiveCameraDraws) {
    const RayTree tree = one_ray({1, 0.5f, 2}, {0, 0, 1}, StopReason::missed);
    CameraSpec fisheye = straight_camera();
    fisheye.projection = Projection::fisheye;
    fisheye.fov = 180;
    EXPECT_TRUE(ray_tree_overlay(tree, fisheye, 200, 100, 10).empty());
    CameraSpec moving = straight_camera();
    moving.motion = {{0, {0, 0, 0}, {0, 0, 1}, {0, 1, 0}}, {1, {1, 0, 0}, {1, 0, 1}, {0, 1, 0}}};
    EXPECT_TRUE(ray_tree_overlay(tree, moving, 200, 100, 10).empty());
}

TEST(RayTreeOverlay, TheShowcasesTreesLieOnTheirPixelsWithEveryFeeler) {
    const Scene scene = load_scene(std::string(GLINT_SOURCE_DIR) + "/scenes/showcase.yaml");
    const CameraSpec spec = scene.camera;
    const int width = scene.settings.width, height = scene.settings.height;
    const World world(scene);
    for (const auto& [x, y] : {std::pair{400, 300}, {120, 520}, {650, 380}, {30, 40}}) {
        const RayTree tree = explain(world, {x, y, 0, 0});
        const auto segments = ray_tree_overlay(tree, spec, width, height, 100);
        ASSERT_FALSE(segments.empty());
        // The eye ray of a pinhole camera is seen end on: its far end lies on the sample.
        EXPECT_EQ(segments[0].node, 0);
        EXPECT_EQ(segments[0].kind, RayKind::primary);
        EXPECT_NEAR(segments[0].to.x, tree.film.x, 2e-3);
        EXPECT_NEAR(segments[0].to.y, tree.film.y, 2e-3);
        // The eye ray's point is in view, so each of its feelers is drawn, from the sample,
        // marked blocked exactly when something shadowed it.
        std::vector<const LightSampleRecord*> feelers;
        for (const LightRecord& light : tree.nodes[0].lights)
            for (const LightSampleRecord& s : light.samples)
                if (s.faces_light) feelers.push_back(&s);
        std::size_t k = 0;
        for (const OverlaySegment& s : segments) {
            if (s.node != 0 || s.kind != RayKind::shadow) continue;
            ASSERT_LT(k, feelers.size());
            const Color shadow = feelers[k++]->shadow;
            EXPECT_EQ(s.blocked, shadow.r < 1 || shadow.g < 1 || shadow.b < 1);
            EXPECT_NEAR(s.from.x, tree.film.x, 2e-3);
            EXPECT_NEAR(s.from.y, tree.film.y, 2e-3);
        }
        EXPECT_EQ(k, feelers.size());
        // Every ray of the tree is drawn where it is in view, and nothing else.
        for (const OverlaySegment& s : segments) EXPECT_LT(std::size_t(s.node), tree.nodes.size());
    }
}

}  // namespace
}  // namespace glint
