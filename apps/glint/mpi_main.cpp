// glint-mpi: `glint render` across the ranks of an MPI job,
//   mpirun -np N glint-mpi render SCENE -o OUT [the options of glint render]
// Rank 0 checks that every rank runs the same glint, loads the scene in its sandbox and sends the
// scene's files to the others, checks that they made the same render of it, renders with them
// (cluster/cluster_render.h), and writes the image as glint render would.
#include <mpi.h>
#include <stdlib.h>

#include <algorithm>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <string>

#include "command_errors.h"
#include "glint/cluster/cluster_render.h"
#include "glint/cluster/frame_share.h"
#include "glint/scene/animation.h"
#include "glint/scene/load_scene.h"
#include "mpi_command_line.h"
#include "mpi_transport.h"
#include "render_command.h"
#include "render_setup.h"
#include "scene_broadcast.h"
#include "usage_error.h"

#ifndef GLINT_VERSION
#define GLINT_VERSION "unknown"
#endif

namespace glint::cli {
namespace {

// What decides each rank's share of the render: ranks whose texts differ did not load the same
// scene with the same options.
std::string render_text(const World& world, const RenderOptions& options) {
    return settings_text(world.settings(), options) + ", " +
           std::to_string(world.primitives().size()) + " primitives, " +
           std::to_string(world.lights().size()) + " lights, " +
           std::to_string(world.object_lights().size()) + " emitting objects";
}

// How often a rank rendering a frame alone says it is alive: well within the rank timeout.
std::chrono::duration<double> heartbeat_of(double rank_timeout) {
    return std::chrono::duration<double>(std::min(rank_timeout / 4, 10.0));
}

// Rank 0: glint render, its scene shared and its render across the ranks. A failure after the
// others have the scene ends the whole job.
int run_root(const RenderCommand& command, MpiTransport& transport, double rank_timeout) {
    ClusterStats stats;
    ClusterOptions cluster;
    cluster.rank_timeout = std::chrono::duration<double>(rank_timeout);
    cluster.describe_rank = describe_rank;
    cluster.stats = &stats;
    double share_seconds = 0;
    std::uint64_t share_bytes = 0;
    // What the other ranks wait for: the scene (or word that loading failed), the next frame's
    // number (or word that there is none), or the end of a frame's render.
    enum class Others { scene, frame, render, released } others = Others::scene;
    bool rendered = false;
    RenderBackend backend;
    backend.load = [&](const RenderCommand& c) {
        const LoadOptions options = c.reading.load_options();
        Scene scene;
        try {
            scene = load_scene(c.scene, options);
        } catch (...) {
            share_failure();
            others = Others::released;
            throw;
        }
        {
            const auto start = std::chrono::steady_clock::now();
            const Watchdog watchdog(cluster.rank_timeout, "the sending of the scene's files");
            share_bytes = share_scene(c.scene, scene, options);
            share_seconds =
                std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        }
        others = Others::frame;
        return scene;
    };
    backend.begin_frame = [&](int frame) {
        share_frame(frame);
        others = Others::render;
    };
    backend.check = [&](const World& world, const RenderOptions& options) {
        if (const int r = first_different(render_text(world, options), cluster.rank_timeout); r > 0)
            throw UsageError{describe_rank(r) +
                             " made another render of the scene than rank 0 (another glint "
                             "build, or other options): every rank must be given the same "
                             "command"};
    };
    std::vector<int> frames_by_rank;
    backend.ranks = transport.ranks();
    backend.share_frames = [&](const std::vector<int>& frames, const FrameRendering& rendering,
                               const FrameBook& book, RenderProgress& progress) {
        share_frame(kWholeFrames);
        others = Others::render;
        const bool done = share_frames_as_root(transport, frames, rendering, book, cluster,
                                               progress, &frames_by_rank);
        others = Others::frame;
        rendered = true;
        return done;
    };
    const RenderEngine engine = cluster_engine(transport, cluster);
    backend.engine = [&](const World& world, const RenderOptions& options, RenderProgress& progress,
                         RenderState& state, std::span<const WorkPiece> work) {
        RenderResult result = engine(world, options, progress, state, work);
        others = Others::frame;
        rendered = true;
        return result;
    };
    if (!command.part.empty()) {
        share_failure();
        std::fprintf(stderr,
                     "glint: error: --part: glint-mpi renders the whole image across its ranks; "
                     "parts are for glint render\n");
        return kExitBadInput;
    }
    const int code = run_render(command, backend);
    if (rendered && !command.quiet) {
        std::printf("  ranks %d:", transport.ranks());
        // What each rank rendered: pieces of images shared by tiles, frames rendered whole.
        for (const auto& [what, counts] :
             {std::pair{" pieces", &stats.pieces}, std::pair{" whole frames", &frames_by_rank}}) {
            if (counts->empty()) continue;
            std::printf("%s", what);
            for (const int n : *counts) std::printf(" %d", n);
            std::printf(";");
        }
        std::printf(
            " scene's files sent (%.1f MB) in %.3f s; films summed %d times in %.3f s; "
            "%.1f MB of messages\n",
            double(share_bytes) / 1e6, share_seconds, stats.sums, stats.sum_seconds,
            double(stats.bytes) / 1e6);
    }
    if (others == Others::scene) share_failure();  // it failed before loading: the others end
    if (others == Others::frame) share_end_of_frames();
    if (others == Others::render) {  // they may be anywhere in the frame's set-up or render
        std::fflush(stderr);
        MPI_Abort(MPI_COMM_WORLD, code == 0 ? kExitFailure : code);
    }
    return code;
}

// Every other rank: the scene from rank 0, the same setup, and whatever rank 0 hands out.
int run_worker(const RenderCommand& command, MpiTransport& transport, double rank_timeout) {
    std::string pattern = (std::filesystem::temp_directory_path() / "glint-mpi-XXXXXX").string();
    const char* made = mkdtemp(pattern.data());
    const int code = reporting_errors([&] {
        if (!made) throw std::runtime_error("cannot make a folder for the scene's files");
        const std::filesystem::path folder(made);
        const std::optional<Scene> scene = receive_scene(folder, command.reading.load_options());
        if (!scene) return 0;  // rank 0 says why
        std::filesystem::remove_all(folder);
        while (const std::optional<int> frame = receive_frame()) {
            if (*frame == kWholeFrames) {
                FrameRendering rendering =
                    frame_rendering(command, *scene, requested_aovs(command));
                rendering.heartbeat = heartbeat_of(rank_timeout);
                share_frames_as_worker(transport, rendering);
                continue;
            }
            RenderSetup setup = set_up_render(command, scene_at_frame(*scene, *frame),
                                              requested_aovs(command), false);
            first_different(render_text(*setup.world, setup.options),
                            std::chrono::duration<double>(rank_timeout));
            render_as_worker(*setup.world, setup.options, transport);
        }
        return 0;
    });
    if (made) std::filesystem::remove_all(made);
    if (code != 0) {
        std::fprintf(stderr, "glint-mpi: the error above is %s's: ending the job\n",
                     describe_rank(transport.rank()).c_str());
        std::fflush(stderr);
        MPI_Abort(MPI_COMM_WORLD, code);
    }
    return 0;
}

}  // namespace
}  // namespace glint::cli

int main(int argc, char** argv) {
    using namespace glint::cli;
    std::signal(SIGXFSZ, SIG_IGN);
    int provided = 0;
    MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided);
    int rank = 0;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);

    MpiCommand command;
    if (const std::optional<int> status = parse_mpi_command_line(argc, argv, rank != 0, command)) {
        MPI_Finalize();
        return *status;
    }
    const RenderCommand& render = command.render;
    const double rank_timeout = command.rank_timeout;
    int code = 0;
    {
        MpiTransport transport;
        transport.set_sum_timeout(std::chrono::duration<double>(rank_timeout));
        std::string refusal;
        int status = kExitBadInput;
        try {
            refusal = check_versions(GLINT_VERSION, std::chrono::duration<double>(rank_timeout));
        } catch (const glint::ClusterError& e) {
            refusal = e.what();
            status = kExitFailure;
        }
        if (rank == 0 && !refusal.empty()) {
            std::fprintf(stderr, "glint-mpi: error: %s\n", refusal.c_str());
            std::fflush(stderr);
            MPI_Abort(MPI_COMM_WORLD, status);
        }
        code = rank == 0 ? run_root(render, transport, rank_timeout)
                         : run_worker(render, transport, rank_timeout);
    }
    MPI_Finalize();
    return code;
}
