// A render across ranks (threads here, MPI in glint-mpi): the image, samples and counts of one
// process, bit for bit, for every integrator; checkpoints that resume to the same image; a stop
// that leaves a state to continue from; and a rank that stops answering ends the job in time,
// named.
#include "glint/cluster/cluster_render.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstring>
#include <filesystem>
#include <thread>
#include <vector>

#include "cluster/thread_cluster.h"
#include "common/every_integrator.h"
#include "glint/render/byte_stream.h"
#include "glint/render/counts_codec.h"
#include "glint/render/resume_file.h"

namespace glint {
namespace {

using testing::ThreadCluster;

RenderOptions options() { return testing::small_pieces(1); }

using testing::same_bits;

// Rank 0 and ranks - 1 workers, each a thread, from `state`.
RenderResult render_on_ranks(const World& world, const RenderOptions& o, int ranks,
                             RenderState& state, RenderProgress* progress = nullptr) {
    ThreadCluster cluster(ranks);
    std::vector<std::thread> workers;
    for (int r = 1; r < ranks; ++r)
        workers.emplace_back([&, r] {
            ThreadCluster::Rank transport(cluster, r);
            render_as_worker(world, o, transport);
        });
    ThreadCluster::Rank root(cluster, 0);
    const RenderResult result = render_as_root(world, o, root, state, ClusterOptions{}, progress);
    for (std::thread& w : workers) w.join();
    return result;
}

// A copy of `state` (a state holds atomics and is not copied), through a resume file.
RenderState copy_of(const World& world, const RenderOptions& o, const RenderState& state) {
    const std::filesystem::path file = std::filesystem::path(GLINT_TEST_OUTPUT_DIR) /
                                       ("cluster-copy-" + std::to_string(::getpid()));
    std::filesystem::create_directories(file.parent_path());
    const RenderIdentity id =
        identify_render(GLINT_SOURCE_DIR "/scenes/showcase.yaml", {}, world.settings(), o, "test");
    write_resume_file(file, id, state);
    RenderState copy = read_resume_file(file, id, world.settings());
    std::filesystem::remove(file);
    return copy;
}

void expect_same(const RenderResult& got, const RenderResult& want, const RenderState& state,
                 const RenderState& want_state) {
    EXPECT_TRUE(got.complete);
    EXPECT_TRUE(same_bits(got.image, want.image));
    EXPECT_TRUE(same_bits(got.samples_taken, want.samples_taken));
    EXPECT_EQ(got.rays, want.rays);
    EXPECT_EQ(got.bad_samples.count, want.bad_samples.count);
    EXPECT_EQ(state.tile_passes, want_state.tile_passes);
}

TEST(ClusterRender, ThreeRanksGiveOneProcesssImageForEveryIntegrator) {
    for (const auto& c : testing::every_integrator()) {
        SCOPED_TRACE(c.name);
        const World world(c.scene);
        RenderState one_state = initial_state(world.settings(), options());
        const RenderResult one = render(world, options(), nullptr, &one_state);
        RenderState state = initial_state(world.settings(), options());
        const RenderResult three = render_on_ranks(world, options(), 3, state);
        expect_same(three, one, state, one_state);
    }
}

// Output variables: the one-pixel films' sums and the ids travel with the tiles, the others sum.
TEST(ClusterRender, OutputVariablesAreOneProcesssToo) {
    for (const char* filter : {"box", "gaussian"}) {
        SCOPED_TRACE(filter);
        Scene scene = testing::load_small("distributed-showcase.yaml", 40, 24, 4);
        scene.settings.filter =
            FilterSpec{std::string(filter) == "box" ? FilterKind::box : FilterKind::gaussian};
        RenderOptions o = options();
        o.aovs = parse_aov_list("depth,normal,object,material,samples,diffuse");
        const World world(scene);
        const RenderResult one = render(world, o);
        RenderState state = initial_state(world.settings(), o);
        const RenderResult two = render_on_ranks(world, o, 2, state);
        ASSERT_EQ(two.aovs.size(), one.aovs.size());
        for (std::size_t i = 0; i < one.aovs.size(); ++i) {
            EXPECT_EQ(two.aovs[i].aov, one.aovs[i].aov);
            EXPECT_TRUE(same_bits(two.aovs[i].image, one.aovs[i].image))
                << aov_info(one.aovs[i].aov).name;
        }
        EXPECT_TRUE(same_bits(two.image, one.image));
    }
}

// At every pass boundary the whole render's state is handed to the checkpoint, every rank's
// films summed: a render continued from it gives the uninterrupted image.
TEST(ClusterRender, CheckpointsHoldTheWholeStateAndResumeToTheSameImage) {
    Scene scene = testing::load_small("distributed-showcase.yaml", 40, 24, 8);  // 4 passes
    const World world(scene);
    const RenderResult one = render(world, options());
    RenderOptions o = options();
    std::vector<RenderState> checkpoints;
    o.after_pass = [&](const RenderState& s) { checkpoints.push_back(copy_of(world, o, s)); };
    RenderState state = initial_state(world.settings(), o);
    const RenderResult three = render_on_ranks(world, o, 3, state);
    EXPECT_TRUE(same_bits(three.image, one.image));
    ASSERT_FALSE(checkpoints.empty());
    for (RenderState& saved : checkpoints) {
        EXPECT_GT(saved.passes_done(), 0);
        const RenderResult continued = render(world, options(), nullptr, &saved);
        EXPECT_TRUE(same_bits(continued.image, one.image));
        EXPECT_EQ(continued.rays, one.rays);
    }
}

// Stopped, the job ends once every rank has handed back what it held; its state continues, on
// one process or on ranks, to the uninterrupted image.
TEST(ClusterRender, AStoppedJobLeavesAStateThatContinues) {
    Scene scene = testing::load_small("distributed-showcase.yaml", 40, 24, 8);
    const World world(scene);
    const RenderResult one = render(world, options());
    RenderProgress progress;
    RenderOptions o = options();
    o.after_piece = [&](int, int) { progress.cancel = true; };
    RenderState state = initial_state(world.settings(), o);
    const RenderResult stopped = render_on_ranks(world, o, 3, state, &progress);
    EXPECT_FALSE(stopped.complete);
    EXPECT_LT(state.passes_done(), 4);
    RenderState copy = copy_of(world, o, state);
    EXPECT_TRUE(same_bits(render(world, options(), nullptr, &copy).image, one.image));
    RenderProgress fresh;
    const RenderResult continued = render_on_ranks(world, options(), 2, state, &fresh);
    EXPECT_TRUE(continued.complete);
    EXPECT_TRUE(same_bits(continued.image, one.image));
    EXPECT_EQ(continued.rays, one.rays);
}

// A rank that asks for work and then never answers: rank 0 gives the job up after the timeout,
// naming it, instead of waiting for ever.
TEST(ClusterRender, ARankThatStopsAnsweringEndsTheJobNamingIt) {
    Scene scene = testing::load_small("distributed-showcase.yaml", 40, 24, 8);
    const World world(scene);
    ThreadCluster cluster(2);
    std::thread silent([&] {
        ThreadCluster::Rank transport(cluster, 1);
        RenderState scratch = initial_state(world.settings(), options());
        // Asks once, as a worker does, then says nothing more.
        ByteWriter ask;
        ask.u8(1);
        ask.i32(4);
        ask.u32(0);
        write_counts(ask, RayStats{}, BadSamples{});
        transport.send(0, ask.bytes());
    });
    ThreadCluster::Rank root(cluster, 0);
    RenderState state = initial_state(world.settings(), options());
    ClusterOptions c;
    c.rank_timeout = std::chrono::milliseconds(300);
    c.describe_rank = [](int r) { return "rank " + std::to_string(r) + " (node7)"; };
    const auto start = std::chrono::steady_clock::now();
    try {
        render_as_root(world, options(), root, state, c);
        ADD_FAILURE() << "the job went on without rank 1";
    } catch (const ClusterError& e) {
        EXPECT_NE(std::string(e.what()).find("rank 1 (node7) has not answered for"),
                  std::string::npos)
            << e.what();
    }
    EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(30));
    silent.join();
}

}  // namespace
}  // namespace glint
