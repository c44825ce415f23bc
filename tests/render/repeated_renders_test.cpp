// The library used from a program: many scene loads and renders in a row in one process. Under
// the asan preset, LeakSanitizer checks at the end of the process that nothing leaked; in every
// other build the heap in use after the last round must be that after the first (glibc's
// mallinfo2), so that a leak shows in release builds too.
#include <gtest/gtest.h>
#include <malloc.h>

#include <cstddef>
#include <filesystem>
#include <string>

#include "common/under_sanitizer.h"
#include "glint/render/render.h"
#include "glint/render/world.h"
#include "glint/scene/load_scene.h"

namespace glint {
namespace {

// Meshes with textures, CSG, image textures, area lights, motion blur and NFF: most of what a
// scene can hold.
constexpr const char* kScenes[] = {"meshes.yaml",       "csg.yaml",         "textures.yaml",
                                   "soft-shadows.yaml", "motion-blur.yaml", "jacks.nff"};

void render_every_scene() {
    for (const char* name : kScenes) {
        Scene scene =
            load_scene(std::filesystem::path(GLINT_SOURCE_DIR) / "scenes/features" / name);
        scene.settings.width = 32;
        scene.settings.height = 24;
        const RenderResult result = render(World(std::move(scene)), {});
        ASSERT_TRUE(result.complete) << name;
    }
}

std::size_t heap_in_use() { return mallinfo2().uordblks; }

TEST(RepeatedRenders, TenRoundsOfLoadingAndRenderingHoldNoMoreMemoryThanOne) {
    // Two rounds first: thread pools and caches made on first use are there after them.
    render_every_scene();
    render_every_scene();
    const std::size_t before = heap_in_use();
    for (int round = 0; round < 10; ++round) render_every_scene();
    if (testing::kUnderSanitizer) return;  // its allocator is not glibc's; LeakSanitizer checks
    // Any object of a scene kept each round would add at least its meshes (the spot mesh alone
    // is some 100 KB) ten times over; allow for the allocator's bookkeeping.
    EXPECT_LE(heap_in_use(), before + (std::size_t(256) << 10))
        << "before " << before << " bytes, after " << heap_in_use();
}

}  // namespace
}  // namespace glint
