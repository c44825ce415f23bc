// The per-ray path allocates nothing: tracing eye rays through the showcase (reflection,
// refraction, shadow feelers, textures) performs no heap allocation. This executable replaces
// the global operator new to count allocations.
#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <new>

#include "glint/render/integrators/whitted.h"
#include "glint/scene/yaml/yaml_scene_loader.h"

namespace {
std::atomic<long> g_allocations{0};
}

void* operator new(std::size_t size) {
    ++g_allocations;
    if (void* p = std::malloc(size ? size : 1)) return p;
    throw std::bad_alloc();
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }

namespace glint {
namespace {

TEST(PerRayPath, TracingAllocatesNothing) {
    Scene scene = load_yaml_scene(std::string(GLINT_SOURCE_DIR) + "/scenes/showcase.yaml");
    scene.settings.transparent_shadows = true;
    scene.settings.width = 64;
    scene.settings.height = 48;
    const World world(scene);
    WhittedIntegrator integrator(world);
    RayStats stats;
    const long before = g_allocations;
    for (int y = 0; y < 48; ++y)
        for (int x = 0; x < 64; ++x)
            integrator.trace_eye_ray(world.camera().generate_ray({x + 0.5f, y + 0.5f}), stats);
    EXPECT_EQ(g_allocations - before, 0);
    EXPECT_GT(stats[RayKind::reflected], 0u);
    EXPECT_GT(stats[RayKind::refracted], 0u);
    EXPECT_GT(stats[RayKind::shadow], 0u);
}

}  // namespace
}  // namespace glint
