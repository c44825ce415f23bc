// An animation's frames shared out whole across ranks (threads here, MPI in glint-mpi): each frame
// one process's, bit for bit, rendered once; a stop that leaves every frame in flight a state to
// continue from; checkpoints that continue to the same image; heartbeats that keep a long frame
// alive past the rank timeout; and a silent rank that ends the job, named.
#include "glint/cluster/frame_share.h"

#include <gtest/gtest.h>

#include <atomic>
#include <map>
#include <mutex>
#include <thread>
#include <vector>

#include "cluster/thread_cluster.h"
#include "common/every_integrator.h"
#include "glint/render/byte_stream.h"
#include "glint/render/state_transfer.h"
#include "glint/scene/animation.h"

namespace glint::frame_share_test {
namespace {

using testing::ThreadCluster;

RenderOptions options() { return testing::small_pieces(1); }

// The animation's frames, small, and what rank 0 keeps of them.
class FrameShare : public ::testing::Test {
protected:
    FrameShare() {
        rendering_.tile_size = options().tile_size;
        rendering_.set_up = [this](int frame) {
            return FrameSetup{std::make_unique<World>(scene_at_frame(scene_, frame)), options()};
        };
        book_.fresh_state = [this](int frame) {
            return initial_state(scene_at_frame(scene_, frame).settings, options());
        };
        book_.saved = [this](int frame) -> std::optional<RenderState> {
            const auto found = saved_.find(frame);
            if (found == saved_.end()) return std::nullopt;
            return copy(found->second, frame);
        };
        book_.finished = [this](int frame, int rank, const RenderState& state, bool complete) {
            ++finished_[frame];
            ranks_[frame] = rank;
            if (complete)
                images_[frame] = resolve_image(state);
            else
                saved_.insert_or_assign(frame, copy(state, frame));
        };
        book_.checkpoint = [this](int frame, const RenderState& state) {
            ++checkpoints_[frame];
            saved_.insert_or_assign(frame, copy(state, frame));
        };
    }

    // A state holds atomics and is not copied: through bytes.
    RenderState copy(const RenderState& state, int frame) const {
        ByteWriter out;
        write_state(out, state, options().tile_size);
        RenderState back = book_.fresh_state(frame);
        ByteReader<> in(reinterpret_cast<const unsigned char*>(out.bytes().data()),
                        out.bytes().size(), "short");
        read_state(in, back, options().tile_size);
        return back;
    }

    // Rank 0 and ranks - 1 workers, each a thread, sharing `frames`.
    bool share(const std::vector<int>& frames, int ranks, RenderProgress& progress,
               const ClusterOptions& cluster = {}) {
        ThreadCluster threads(ranks);
        std::vector<std::thread> workers;
        for (int r = 1; r < ranks; ++r)
            workers.emplace_back([&, r] {
                ThreadCluster::Rank transport(threads, r);
                share_frames_as_worker(transport, rendering_);
            });
        ThreadCluster::Rank root(threads, 0);
        const bool done =
            share_frames_as_root(root, frames, rendering_, book_, cluster, progress, &by_rank_);
        for (std::thread& w : workers) w.join();
        return done;
    }

    Image alone(int frame) const {
        const World world(scene_at_frame(scene_, frame));
        return render(world, options()).image;
    }

    Scene scene_ = testing::load_small("features/animation.yaml", 24, 16, 8);
    FrameRendering rendering_;
    FrameBook book_;
    std::map<int, RenderState> saved_;
    std::map<int, Image> images_;
    std::map<int, int> finished_, ranks_, checkpoints_;
    std::vector<int> by_rank_;
};

TEST_F(FrameShare, EveryFrameIsOneProcesssRenderedOnce) {
    RenderProgress progress;
    EXPECT_TRUE(share({1, 2, 3, 4, 5}, 3, progress));
    ASSERT_EQ(images_.size(), 5u);
    for (const auto& [frame, image] : images_) {
        EXPECT_EQ(finished_[frame], 1) << frame;
        EXPECT_TRUE(testing::same_bits(image, alone(frame))) << frame;
    }
    EXPECT_FALSE(testing::same_bits(images_[1], images_[5]));
    ASSERT_EQ(by_rank_.size(), 3u);
    EXPECT_EQ(by_rank_[0] + by_rank_[1] + by_rank_[2], 5);
}

TEST_F(FrameShare, AStopLeavesEveryFrameInFlightAStateThatContinues) {
    RenderProgress progress;
    // Each render holds after its first piece until the stop reaches it, so that every rank has
    // a frame in flight when rank 0 stops.
    std::atomic<int> holding{0};
    rendering_.hold = [&](const RenderProgress& own) {
        return [&](int pieces) {
            if (pieces != 1) return;
            if (++holding == 3) progress.stop_after_pass = true;
            while (!own.stop_after_pass) std::this_thread::sleep_for(std::chrono::milliseconds(1));
        };
    };
    EXPECT_FALSE(share({0, 1, 2, 3, 4}, 3, progress));
    EXPECT_TRUE(images_.empty());
    ASSERT_EQ(saved_.size(), 3u);
    for (const auto& [frame, state] : saved_) EXPECT_EQ(state.passes_done(), 1) << frame;

    rendering_.hold = {};
    RenderProgress again;
    EXPECT_TRUE(share({0, 1, 2, 3, 4}, 2, again));
    ASSERT_EQ(images_.size(), 5u);
    for (const auto& [frame, image] : images_)
        EXPECT_TRUE(testing::same_bits(image, alone(frame))) << frame;
}

TEST_F(FrameShare, CheckpointsContinueToTheSameImage) {
    rendering_.checkpoint_every = std::chrono::seconds(0);
    RenderProgress progress;
    EXPECT_TRUE(share({0, 6}, 2, progress));
    // Four passes of two samples: a checkpoint after each but the last, the newest replacing
    // one not yet sent.
    EXPECT_GE(checkpoints_[0], 1);
    ASSERT_GE(checkpoints_[6], 1);
    EXPECT_GE(saved_.at(6).passes_done(), 1);
    EXPECT_LE(saved_.at(6).passes_done(), 3);
    images_.clear();
    rendering_.checkpoint_every.reset();
    EXPECT_TRUE(share({6}, 2, progress));
    EXPECT_TRUE(testing::same_bits(images_.at(6), alone(6)));
}

// A frame that takes longer than the rank timeout, its rank saying it is alive meanwhile.
TEST_F(FrameShare, HeartbeatsKeepALongFrameAlive) {
    rendering_.heartbeat = std::chrono::milliseconds(20);
    rendering_.hold = [](const RenderProgress&) {
        return [](int) { std::this_thread::sleep_for(std::chrono::milliseconds(10)); };
    };
    ClusterOptions cluster;
    cluster.rank_timeout = std::chrono::milliseconds(150);
    RenderProgress progress;
    const auto start = std::chrono::steady_clock::now();
    EXPECT_TRUE(share({0, 1}, 2, progress, cluster));
    EXPECT_GT(std::chrono::steady_clock::now() - start, cluster.rank_timeout);
    EXPECT_EQ(images_.size(), 2u);
}

// A rank that takes a frame and is never heard from again: rank 0 gives the job up after the
// timeout, naming it and its frame.
TEST_F(FrameShare, ASilentRankEndsTheJobNamingIt) {
    ThreadCluster threads(2);
    std::thread silent([&] {
        ThreadCluster::Rank transport(threads, 1);
        while (!transport.receive(std::chrono::milliseconds(10))) {
        }
    });
    ThreadCluster::Rank root(threads, 0);
    ClusterOptions cluster;
    cluster.rank_timeout = std::chrono::milliseconds(300);
    cluster.describe_rank = [](int r) { return "rank " + std::to_string(r) + " (node7)"; };
    RenderProgress progress;
    const auto start = std::chrono::steady_clock::now();
    try {
        share_frames_as_root(root, {0, 1, 2, 3, 4, 5, 6, 7}, rendering_, book_, cluster, progress);
        ADD_FAILURE() << "the job went on without rank 1";
    } catch (const ClusterError& e) {
        EXPECT_NE(std::string(e.what()).find("rank 1 (node7) has said nothing for"),
                  std::string::npos)
            << e.what();
        EXPECT_NE(std::string(e.what()).find("while rendering frame 1"), std::string::npos);
    }
    EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(30));
    silent.join();
}

}  // namespace
}  // namespace glint::frame_share_test
