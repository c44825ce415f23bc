// The scene-level BVH against the brute-force list on the same primary rays of SPD databases
// (from ../shared/data/spd; skipped when absent). Ratios are recorded in bench/README.md.
#include <benchmark/benchmark.h>

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "glint/render/world.h"
#include "glint/scene/nff/nff_to_scene.h"

namespace glint {
namespace {

const std::filesystem::path kSpd = std::filesystem::path(GLINT_SOURCE_DIR) / "../shared/data/spd";

// Eye rays through a 64 x 64 grid of the image.
std::vector<Ray> primary_rays(const World& world) {
    std::vector<Ray> rays;
    const RenderSettings& s = world.settings();
    for (int y = 0; y < 64; ++y)
        for (int x = 0; x < 64; ++x)
            rays.push_back(world.camera().generate_ray(
                {(x + 0.5f) * s.width / 64.0f, (y + 0.5f) * s.height / 64.0f}));
    return rays;
}

void closest_hits(benchmark::State& state, const std::string& file, AccelKind accel) {
    if (!std::filesystem::exists(kSpd / file)) {
        state.SkipWithError("the SPD databases are not here");
        return;
    }
    const Scene scene = load_nff_scene(kSpd / file);
    const World world(scene, accel);
    const std::vector<Ray> rays = primary_rays(world);
    std::size_t hits = 0;
    for (auto _ : state) {
        for (const Ray& ray : rays)
            hits += world.intersect(ray, {}, kVisibleToCameraRays).has_value();
        benchmark::DoNotOptimize(hits);
    }
    state.SetItemsProcessed(state.iterations() * rays.size());
}

void register_all() {
    for (const char* file : {"balls.nff", "gears.nff", "tetra.nff", "tree.nff"}) {
        benchmark::RegisterBenchmark((std::string("Bvh/") + file).c_str(), closest_hits, file,
                                     AccelKind::bvh);
        benchmark::RegisterBenchmark((std::string("ListReference/") + file).c_str(), closest_hits,
                                     file, AccelKind::list)
            ->Iterations(1);
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
