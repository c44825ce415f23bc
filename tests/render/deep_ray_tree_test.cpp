// The deepest ray tree a scene can ask for (kMaxDepth, under --max-ray-depth) fits on a worker
// thread's stack: a room of two facing mirrors, whose every eye ray is reflected to the last
// level, rendered by both integrators and explained. Run under the sanitizers too, whose frames
// are the largest.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "glint/render/explain/explain.h"
#include "glint/render/ray_stats.h"
#include "glint/render/render.h"
#include "glint/render/world.h"
#include "glint/scene/yaml/yaml_scene_loader.h"

namespace glint {
namespace {

const std::string kMirrorRoom = R"(
camera: {from: [0, 0, 0], at: [0, 0, 1], fov: 20}
materials:
  mirror: {color: [1, 1, 1], ka: 0.1, kd: 0.1, ks: 0, reflect: 1}
lights:
  - {type: point, position: [0, 0, 0], color: [1, 1, 1]}
objects:
  - {type: plane, point: [0, 0, 2], normal: [0, 0, -1], material: mirror}
  - {type: plane, point: [0, 0, -2], normal: [0, 0, 1], material: mirror}
)";

TEST(DeepRayTree, TheCeilingDepthRendersAndExplainsWithoutOverflowingAStack) {
    for (const std::string integrator : {"whitted", "distributed"}) {
        SCOPED_TRACE(integrator);
        Scene scene = parse_yaml_scene("image: {width: 8, height: 8, min_weight: 0, integrator: " +
                                           integrator + "}\n" + kMirrorRoom,
                                       "mirrors.yaml");
        scene.settings.max_depth = kMaxDepth;
        const World world(std::move(scene));
        const RenderResult result = render(world, RenderOptions{});
        EXPECT_EQ(result.bad_samples.count, 0u);
        // Every eye ray hits a mirror and is reflected until the last level.
        EXPECT_EQ(result.rays.traced[std::size_t(RayKind::reflected)],
                  std::uint64_t(8 * 8) * (kMaxDepth - 1));
        for (const Color& c : result.image.pixels) ASSERT_TRUE(std::isfinite(c.r) && c.r > 0);

        const RayTree tree = explain(world, {4, 4, 0, 0});
        EXPECT_EQ(tree.nodes.size(), std::size_t(kMaxDepth));
        EXPECT_EQ(evaluate(tree), tree.sample_value);
    }
}

}  // namespace
}  // namespace glint
