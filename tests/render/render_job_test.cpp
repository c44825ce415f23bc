// The render job: its observer sees every piece of work once, a job cancelled and run again
// gives the uninterrupted image bit for bit, and its image can be read while it renders.
#include "glint/render/render_job.h"

#include <gtest/gtest.h>

#include <atomic>
#include <mutex>
#include <set>
#include <stdexcept>
#include <string>
#include <thread>
#include <utility>
#include <vector>

namespace glint {
namespace {

// 40 x 24 pixels in tiles of 16 (3 x 2 tiles), 4 samples in passes of 2.
Scene small_scene() {
    Scene scene;
    scene.settings.width = 40;
    scene.settings.height = 24;
    scene.settings.samples_per_pixel = 4;
    scene.settings.integrator = IntegratorKind::distributed;
    scene.camera.from = {0, 0, -4};
    scene.camera.at = {0, 0, 0};
    scene.materials = {Material{}};
    scene.objects.push_back({Sphere{{0, 0, 0}, 1}, 0});
    scene.lights.push_back(PointLight{{-3, 4, -4}, {1, 1, 1}, {}});
    return scene;
}

RenderOptions small_options() {
    RenderOptions options;
    options.tile_size = 16;
    options.pass_size = 2;
    options.seed = 3;
    return options;
}

TEST(RenderJob, TheObserverSeesEveryPieceOnceAndTheImageIsRendersOwn) {
    const World world(small_scene());
    RenderJob job(world, small_options());
    std::mutex lock;
    std::multiset<std::pair<int, int>> pieces;
    const RenderResult result = job.run([&](const WorkPiece& p) {
        const std::lock_guard guard(lock);
        pieces.insert({p.pass, p.tile});
    });
    EXPECT_TRUE(result.complete);
    EXPECT_TRUE(job.done());
    ASSERT_EQ(pieces.size(), 2u * 6u);
    for (int pass = 0; pass < 2; ++pass)
        for (int tile = 0; tile < 6; ++tile) EXPECT_EQ(pieces.count({pass, tile}), 1u);
    EXPECT_EQ(result.image.pixels, render(world, small_options()).image.pixels);
}

TEST(RenderJob, CancelledAndRunAgainItGivesTheUninterruptedImage) {
    const World world(small_scene());
    RenderJob job(world, small_options());
    std::atomic<int> seen{0};
    const RenderResult stopped = job.run([&](const WorkPiece&) {
        if (++seen == 3) job.cancel();
    });
    EXPECT_FALSE(stopped.complete);
    EXPECT_FALSE(job.done());
    const RenderResult finished = job.run();  // the stop is forgotten
    EXPECT_TRUE(finished.complete);
    const RenderResult whole = render(world, small_options());
    EXPECT_EQ(finished.image.pixels, whole.image.pixels);
    EXPECT_EQ(finished.rays.total(), whole.rays.total());
}

TEST(RenderJob, AStopAskedBeforeTheRunHoldsForIt) {
    // A page may move the camera before the thread that runs the job has started.
    const World world(small_scene());
    RenderJob job(world, small_options());
    job.cancel();
    int pieces = 0;
    const RenderResult cancelled = job.run([&](const WorkPiece&) { ++pieces; });
    EXPECT_FALSE(cancelled.complete);
    EXPECT_EQ(pieces, 0);
    job.stop_after_pass();  // after the first pass, which leaves an image to show
    EXPECT_FALSE(job.run().complete);
    EXPECT_EQ(job.state().passes_done(), 1);
    const RenderResult finished = job.run();  // each stop held for one run only
    EXPECT_TRUE(finished.complete);
    EXPECT_EQ(finished.image.pixels, render(world, small_options()).image.pixels);
}

TEST(RenderJob, ItsImageCanBeReadWhileItRenders) {
    const World world(small_scene());
    RenderJob job(world, small_options());
    std::atomic<bool> running{true};
    std::atomic<int> reads{0};
    std::thread reader([&] {
        while (running) {
            const Image so_far = job.image_so_far();
            EXPECT_EQ(so_far.width, 40);
            ++reads;
        }
    });
    // The first piece done waits for a read, so that one comes while the job renders however
    // the threads are scheduled.
    const RenderResult result = job.run([&](const WorkPiece&) {
        while (reads == 0) std::this_thread::yield();
    });
    running = false;
    reader.join();
    EXPECT_EQ(job.image_so_far().pixels, result.image.pixels);
}

TEST(RenderJob, ItsResultSoFarHoldsTheOutputVariablesOfItsFilms) {
    const World world(small_scene());
    RenderOptions options = small_options();
    options.aovs.add(Aov::depth);
    options.aovs.add(Aov::samples);
    RenderJob job(world, options);
    job.stop_after_pass();
    job.run();
    const RenderResult half = job.result_so_far();
    ASSERT_EQ(half.aovs.size(), 1u);  // the samples taken are the state's, between runs
    EXPECT_EQ(half.aovs[0].aov, Aov::depth);
    EXPECT_GT(half.rays.total(), 0u);
    const RenderResult whole = job.run();
    const RenderResult so_far = job.result_so_far();
    EXPECT_EQ(so_far.image.pixels, whole.image.pixels);
    ASSERT_EQ(so_far.aovs.size(), 1u);
    EXPECT_EQ(so_far.aovs[0].image.pixels, whole.aovs[0].image.pixels);
    EXPECT_EQ(so_far.rays.total(), whole.rays.total());
}

}  // namespace
}  // namespace glint

namespace glint {
namespace {

// Tile after tile, each through every pass, from the last tile back, over two runs: the image and
// the counts of one render() from the start, for a film that splats across tiles and for the
// photon integrator, which builds a photon map for each pass.
TEST(RenderJob, AWorkListInAnyOrderOfTilesGivesTheRendersImage) {
    for (const IntegratorKind integrator : {IntegratorKind::distributed, IntegratorKind::photon}) {
        Scene scene = small_scene();
        scene.settings.integrator = integrator;
        const World world(scene);
        const RenderResult whole = render(world, small_options());
        RenderJob job(world, small_options());
        const int passes = integrator == IntegratorKind::photon ? 4 : 2;  // photon: 1 a pass
        std::vector<WorkPiece> first, second;
        for (int tile = 5; tile >= 0; --tile)
            for (int pass = 0; pass < passes; ++pass)
                (tile >= 3 ? first : second).push_back({pass, tile});
        EXPECT_TRUE(job.run(first).complete);
        EXPECT_FALSE(job.done());
        EXPECT_EQ(job.state().passes_done(), 0);
        EXPECT_EQ(job.progress().tiles_total, int(first.size()));
        const RenderResult result = job.run(second);
        EXPECT_TRUE(result.complete);
        EXPECT_TRUE(job.done());
        EXPECT_EQ(result.image.pixels, whole.image.pixels) << integrator_name(integrator);
        EXPECT_EQ(result.rays, whole.rays) << integrator_name(integrator);
    }
}

TEST(RenderJob, AWorkListMustTakeEachTilesPassesInTurnOnce) {
    const World world(small_scene());
    RenderJob job(world, small_options());
    const auto refused = [&](std::vector<WorkPiece> work) {
        try {
            job.run(work);
        } catch (const std::invalid_argument& e) {
            return std::string(e.what());
        }
        return std::string("accepted");
    };
    EXPECT_NE(refused({{1, 0}}).find("tile 0 is at pass 0, not 1"), std::string::npos);
    EXPECT_NE(refused({{0, 2}, {0, 2}}).find("tile 2 is at pass 1, not 0"), std::string::npos);
    EXPECT_NE(refused({{0, 6}}).find("outside the render's 2 passes of 6 tiles"),
              std::string::npos);
    EXPECT_NE(refused({{2, 0}}).find("outside"), std::string::npos);
    EXPECT_EQ(job.state().passes_done(), 0);           // nothing was rendered
    EXPECT_EQ(refused({{1, 0}, {0, 0}}), "accepted");  // in any order within the list
    EXPECT_EQ(job.state().tile_passes[0], 2);
}

}  // namespace
}  // namespace glint
