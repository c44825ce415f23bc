// glint-mpi under mpirun with three ranks on this machine: the image of one glint render, bit for
// bit, for every integrator and with output variables; an animation's frames, whole and shared;
// a stopped job or sequence that resumes; a rank given another command refused; a rank killed or
// stopped ends the job in bounded time, named.
#include <gtest/gtest.h>

#include <chrono>
#include <csignal>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include "cli/cli_fixture.h"
#include "common/under_sanitizer.h"

namespace glint {
namespace {

// mpirun as root needs leave; Open MPI's own allocations are not the sanitizer's business.
const std::string kEnvironment =
    "export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 "
    "ASAN_OPTIONS=detect_leaks=0; ";

class Mpi : public Cli {
protected:
    // mpirun with three ranks of glint-mpi render `args`, each rank on one thread.
    Outcome mpirun(const std::string& args, int ranks = 3) const {
        return run(kEnvironment, "mpirun --oversubscribe -np " + std::to_string(ranks) +
                                     " '" GLINT_MPI_BINARY "' render --threads 1 " + args);
    }
    // The process of the rank of mpirun `parent`: its child whose environment names the rank.
    static pid_t rank_process(pid_t parent, int rank) {
        std::ifstream children("/proc/" + std::to_string(parent) + "/task/" +
                               std::to_string(parent) + "/children");
        pid_t child = 0;
        while (children >> child) {
            std::ifstream environ("/proc/" + std::to_string(child) + "/environ");
            const std::string all((std::istreambuf_iterator<char>(environ)), {});
            if (all.find("OMPI_COMM_WORLD_RANK=" + std::to_string(rank) + '\0') !=
                std::string::npos)
                return child;
        }
        return 0;
    }
    std::vector<std::string> mpirun_args(const std::vector<std::string>& more) const {
        std::vector<std::string> a = {"mpirun",         "--oversubscribe", "-np",       "3",
                                      GLINT_MPI_BINARY, "render",          "--threads", "1"};
        a.insert(a.end(), more.begin(), more.end());
        return a;
    }
    // Sends `signal` to `victim`, a rank of mpirun `pid`, and waits up to a minute for the job
    // to end; kills what is left if it does not.
    static bool signal_ends_job(pid_t pid, pid_t victim, int signal) {
        const auto start = std::chrono::steady_clock::now();
        kill(victim, signal);
        int status = 0;
        while (waitpid(pid, &status, WNOHANG) == 0 &&
               std::chrono::steady_clock::now() - start < std::chrono::seconds(60))
            std::this_thread::sleep_for(std::chrono::milliseconds(20));
        const bool ended = waitpid(pid, &status, WNOHANG) != 0 || WIFEXITED(status);
        if (!ended) {
            kill(victim, SIGKILL);
            kill(pid, SIGKILL);
            waitpid(pid, &status, 0);
        }
        return ended;
    }
    // Waits until `ranks` ranks say they hold (GLINT_TEST_HOLD_AFTER_TILES), two minutes at most.
    bool ranks_hold(int ranks) const {
        const auto holding = [&] {
            const std::string err = slurp(dir_ / "stderr.txt");
            int n = 0;
            for (std::size_t at = 0; (at = err.find("glint: holding", at)) != std::string::npos;
                 ++at)
                ++n;
            return n;
        };
        for (int waited = 0; holding() < ranks && waited < 120000; waited += 10)
            std::this_thread::sleep_for(std::chrono::milliseconds(10));
        return holding() >= ranks;
    }
    static std::vector<std::string> environment() {
        return {"OMPI_ALLOW_RUN_AS_ROOT=1", "OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1",
                "ASAN_OPTIONS=detect_leaks=0"};
    }
};

TEST_F(Mpi, ThreeRanksWriteTheImageOfOneProcessForEveryIntegrator) {
    struct Case {
        std::string scene, options;
    };
    const std::string small = " --width 48 --height 32 --seed 5";
    for (const Case& c : std::vector<Case>{
             {"showcase.yaml", ""},
             {"distributed-showcase.yaml", " --spp 8"},
             {"features/adaptive.yaml", " --spp 32"},
             {"features/cornell-box.yaml", " --integrator path --spp 4"},
             {"features/cornell-box.yaml", " --integrator light --spp 4"},
             {"features/caustics.yaml", " --integrator photon --spp 2"},
             {"features/cone-tracing.yaml", ""},
             {"features/beam-tracing.yaml", ""},
             {"features/textures.yaml", " --aov depth,normal,object,diffuse,samples"}}) {
        SCOPED_TRACE(c.scene + c.options);
        const std::string args = scene(c.scene) + small + c.options + " -q";
        const Outcome one = run_glint("render " + args + " -o one.exr");
        ASSERT_EQ(one.exit_code, 0) << one.err;
        const Outcome three = mpirun(args + " -o three.exr");
        ASSERT_EQ(three.exit_code, 0) << three.err;
        EXPECT_TRUE(slurp(dir_ / "one.exr") == slurp(dir_ / "three.exr"));
    }
    // The summary adds up every rank's rays.
    const std::string args = scene("showcase.yaml") + small;
    const Outcome one = run_glint("render " + args + " -o one.png");
    const Outcome three = mpirun(args + " -o three.png");
    ASSERT_EQ(three.exit_code, 0) << three.err;
    const auto rays = [](const std::string& out) { return out.substr(out.find("  rays")); };
    EXPECT_EQ(rays(three.out).substr(0, 30), rays(one.out).substr(0, 30)) << three.out;
}

// An animation's frames as one process renders them, output variables included: three whole, a
// frame to a rank, and the last, fewer than half the ranks, across the ranks. The frames a
// resumed sequence skips are skipped by every rank.
TEST_F(Mpi, ThreeRanksRenderAnAnimationsFramesAsOneProcess) {
    const std::string args = scene("features/animation.yaml") +
                             " --width 32 --height 24 --spp 4 --seed 5 --aov depth,object";
    const Outcome one = run_glint("render " + args + " -q --frames 0..3 -o 'one.#.exr'");
    ASSERT_EQ(one.exit_code, 0) << one.err;
    const Outcome three = mpirun(args + " --frames 0..3 -o 'three.#.exr'");
    ASSERT_EQ(three.exit_code, 0) << three.err;
    EXPECT_NE(three.out.find("whole frames 1 1 1;"), std::string::npos) << three.out;
    EXPECT_NE(three.out.find("(frame 2, rank "), std::string::npos) << three.out;
    EXPECT_NE(three.out.find("(frame 3; "), std::string::npos) << three.out;
    for (const std::string f : {"0", "1", "2", "3"}) {
        ASSERT_TRUE(fs::exists(dir_ / ("three." + f + ".exr"))) << f;
        EXPECT_TRUE(slurp(dir_ / ("one." + f + ".exr")) == slurp(dir_ / ("three." + f + ".exr")))
            << f;
    }
    // A resume file holds no output variables: resumed without them.
    const std::string plain = scene("features/animation.yaml") +
                              " --width 32 --height 24 --spp 4 --seed 5 -q --frames 0..4";
    ASSERT_EQ(run_glint("render " + plain + " -o 'one.#.png'").exit_code, 0);
    ASSERT_EQ(mpirun(plain + " -o 'three.#.png'").exit_code, 0);
    fs::remove(dir_ / "three.3.png");
    const auto written = fs::last_write_time(dir_ / "three.1.png");
    const Outcome resumed = mpirun(plain + " -o 'three.#.png' --resume");
    ASSERT_EQ(resumed.exit_code, 0) << resumed.err;
    EXPECT_TRUE(slurp(dir_ / "one.3.png") == slurp(dir_ / "three.3.png"));
    EXPECT_EQ(fs::last_write_time(dir_ / "three.1.png"), written);
}

// Ctrl-C on rank 0 while every rank renders a frame of its own: each frame in flight leaves its
// partial image and resume file, and the sequence resumes at them to one process's frames.
TEST_F(Mpi, AStoppedSequenceResumesAtTheFramesInFlight) {
    const std::vector<std::string> options = {
        std::string(GLINT_SOURCE_DIR) + "/scenes/features/animation.yaml",
        "--width",
        "48",
        "--height",
        "32",
        "--spp",
        "8",
        "--seed",
        "3",
        "-q",
        "--frames",
        "0..5"};
    std::string line;
    for (const std::string& o : options) line += "'" + o + "' ";
    ASSERT_EQ(run_glint("render --threads 1 " + line + " -o 'one.#.png'").exit_code, 0);
    std::vector<std::string> environment = this->environment();
    environment.push_back("GLINT_TEST_HOLD_AFTER_TILES=2");
    std::vector<std::string> args = options;
    args.insert(args.end(), {"-o", (dir_ / "out.#.png").string()});
    const pid_t pid = spawn(mpirun_args(args), environment);
    ASSERT_GT(pid, 0);
    // Every rank holding a frame of its own.
    ASSERT_TRUE(ranks_hold(3)) << slurp(dir_ / "stderr.txt");
    const pid_t root = rank_process(pid, 0);
    ASSERT_GT(root, 0);
    kill(root, SIGINT);
    int status = 0;
    waitpid(pid, &status, 0);
    const std::string err = slurp(dir_ / "stderr.txt");
    EXPECT_NE(err.find("frames 0, 1, 2 stopped"), std::string::npos) << err;
    EXPECT_NE(err.find("--frames 0..5 --resume"), std::string::npos) << err;
    for (const std::string f : {"0", "1", "2"}) {
        EXPECT_TRUE(fs::exists(dir_ / ("out." + f + ".png.resume"))) << f;
        EXPECT_TRUE(fs::exists(dir_ / ("out." + f + ".partial.png"))) << f;
        EXPECT_FALSE(fs::exists(dir_ / ("out." + f + ".png"))) << f;
    }

    const Outcome resumed = mpirun(line + "-o 'out.#.png' --resume");
    ASSERT_EQ(resumed.exit_code, 0) << resumed.err;
    for (const std::string f : {"0", "1", "2", "3", "4", "5"}) {
        EXPECT_TRUE(slurp(dir_ / ("out." + f + ".png")) == slurp(dir_ / ("one." + f + ".png")))
            << f;
        EXPECT_FALSE(fs::exists(dir_ / ("out." + f + ".png.resume"))) << f;
    }
}

TEST_F(Mpi, AStoppedJobResumesToTheImageOfOneRun) {
    const std::vector<std::string> options = {
        std::string(GLINT_SOURCE_DIR) + "/scenes/distributed-showcase.yaml",
        "--width",
        "64",
        "--height",
        "48",
        "--spp",
        "32",
        "--seed",
        "3",
        "-q"};
    std::string line;
    for (const std::string& o : options) line += "'" + o + "' ";
    ASSERT_EQ(run_glint("render --threads 1 " + line + " -o whole.exr").exit_code, 0);
    std::vector<std::string> environment = this->environment();
    environment.push_back("GLINT_TEST_HOLD_AFTER_TILES=3");
    std::vector<std::string> args = options;
    args.insert(args.end(), {"-o", (dir_ / "out.exr").string()});
    const pid_t pid = spawn(mpirun_args(args), environment);
    ASSERT_GT(pid, 0);
    for (int waited = 0; !holding() && waited < 120000; waited += 10)
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    ASSERT_TRUE(holding()) << slurp(dir_ / "stderr.txt");
    const pid_t root = rank_process(pid, 0);
    ASSERT_GT(root, 0);
    kill(root, SIGINT);  // as Ctrl-C on rank 0's terminal
    int status = 0;
    waitpid(pid, &status, 0);
    const std::string err = slurp(dir_ / "stderr.txt");
    EXPECT_NE(err.find("--resume"), std::string::npos) << err;
    ASSERT_TRUE(fs::exists(dir_ / "out.exr.resume")) << err;
    EXPECT_FALSE(fs::exists(dir_ / "out.exr"));

    const Outcome resumed = mpirun(line + "-o out.exr --resume");
    ASSERT_EQ(resumed.exit_code, 0) << resumed.err;
    EXPECT_TRUE(slurp(dir_ / "out.exr") == slurp(dir_ / "whole.exr"));
    EXPECT_FALSE(fs::exists(dir_ / "out.exr.resume"));
}

// A scene in the test's folder naming a mesh by its absolute path in a folder it may read: the
// other ranks read the mesh from their own disk, checked against the one rank 0 sent.
TEST_F(Mpi, AFileNamedByItsAbsolutePathIsReadOnEveryHostAndChecked) {
    const std::string meshes = std::string(GLINT_SOURCE_DIR) + "/tests/data/meshes";
    std::ofstream(dir_ / "mesh.yaml") << "camera: {from: [0, 0.1, 0.4], at: [0, 0.1, 0], fov: 40}\n"
                                         "lights: [{type: point, position: [1, 1, 1]}]\n"
                                         "objects: [{type: mesh, file: "
                                      << meshes << "/bunny_npm.obj}]\n";
    const std::string args = "mesh.yaml --width 32 --height 24 -q --allow-read '" + meshes + "'";
    ASSERT_EQ(run_glint("render " + args + " -o one.exr").exit_code, 0);
    const Outcome three = mpirun(args + " -o three.exr");
    ASSERT_EQ(three.exit_code, 0) << three.err;
    EXPECT_TRUE(slurp(dir_ / "one.exr") == slurp(dir_ / "three.exr"));
}

TEST_F(Mpi, ARankGivenAnotherCommandIsRefusedAtTheStart) {
    const std::string mpi = "'" GLINT_MPI_BINARY "' render --threads 1 " + scene("showcase.yaml") +
                            " --width 32 --height 24 -q -o x.png";
    const Outcome o =
        run(kEnvironment, "mpirun --oversubscribe -np 2 " + mpi + " : -np 1 " + mpi + " --spp 4");
    EXPECT_NE(o.exit_code, 0);
    EXPECT_NE(o.err.find("rank 2 ("), std::string::npos) << o.err;
    EXPECT_NE(o.err.find("made another render of the scene than rank 0"), std::string::npos)
        << o.err;
    EXPECT_FALSE(fs::exists(dir_ / "x.png"));
}

// With frames shared out whole, the rank's own frame is checked against rank 0's.
TEST_F(Mpi, ARankGivenAnotherCommandIsRefusedAtItsFirstFrame) {
    const std::string mpi = "'" GLINT_MPI_BINARY "' render --threads 1 " +
                            scene("features/animation.yaml") +
                            " --width 32 --height 24 --frames 0..2 -q -o 'x.#.png'";
    const Outcome o =
        run(kEnvironment, "mpirun --oversubscribe -np 2 " + mpi + " : -np 1 " + mpi + " --spp 4");
    EXPECT_NE(o.exit_code, 0);
    EXPECT_NE(o.err.find("made another render of frame 2 than rank 0"), std::string::npos) << o.err;
    EXPECT_NE(o.err.find("the error above is rank 2's"), std::string::npos) << o.err;
    EXPECT_FALSE(fs::exists(dir_ / "x.2.png"));
}

TEST_F(Mpi, BadInputIsReportedOnceByRankZero) {
    std::ofstream(dir_ / "bad.yaml") << "camera: {from: [0, 0, -5], at: [0, 0, 0]\nobjects: [\n";
    const Outcome bad = mpirun("bad.yaml -o x.png");
    EXPECT_EQ(bad.exit_code, 2);
    EXPECT_NE(bad.err.find("bad.yaml:2:1: error:"), std::string::npos) << bad.err;
    EXPECT_EQ(bad.err.find("MPI_ABORT"), std::string::npos) << bad.err;
    const Outcome part = mpirun(scene("showcase.yaml") + " --part 1/2 -o x.png");
    EXPECT_EQ(part.exit_code, 2);
    EXPECT_NE(part.err.find("parts are for glint render"), std::string::npos) << part.err;
}

// A rank killed outright: mpirun ends the job and names it; a rank stopped (a host that hangs):
// rank 0 gives up after --rank-timeout and names it. Neither hangs.
TEST_F(Mpi, ARankKilledOrStoppedEndsTheJobNamingIt) {
    for (const int signal : {SIGKILL, SIGSTOP}) {
        SCOPED_TRACE(signal == SIGKILL ? "killed" : "stopped");
        const pid_t pid =
            spawn(mpirun_args({std::string(GLINT_SOURCE_DIR) + "/scenes/distributed-showcase.yaml",
                               "--width", "320", "--height", "240", "--spp", "64", "--rank-timeout",
                               "2", "-o", (dir_ / "out.exr").string()}),
                  environment());
        ASSERT_GT(pid, 0);
        // Once the render is under way: its first progress line.
        for (int waited = 0; waited < 120000; waited += 10) {
            if (slurp(dir_ / "stderr.txt").find("% done") != std::string::npos) break;
            std::this_thread::sleep_for(std::chrono::milliseconds(10));
        }
        const pid_t victim = rank_process(pid, 2);
        ASSERT_GT(victim, 0) << slurp(dir_ / "stderr.txt");
        EXPECT_TRUE(signal_ends_job(pid, victim, signal)) << "the job did not end in a minute";
        const std::string err = slurp(dir_ / "stderr.txt");
        if (signal == SIGKILL)
            EXPECT_NE(err.find("rank 2"), std::string::npos) << err;
        else
            EXPECT_NE(err.find("rank 2 ("), std::string::npos) << err;
        EXPECT_NE(err.find(signal == SIGKILL ? "signal 9" : "has not answered"), std::string::npos)
            << err;
        EXPECT_FALSE(fs::exists(dir_ / "out.exr"));
        kill(victim, SIGCONT);
    }
}

// A rank stopped while it renders a frame of its own: its heartbeats stop, and rank 0 gives up
// after --rank-timeout, naming it and its frame.
TEST_F(Mpi, ARankStoppedInItsOwnFrameEndsTheJobNamingIt) {
    std::vector<std::string> environment = this->environment();
    environment.push_back("GLINT_TEST_HOLD_AFTER_TILES=1");
    const pid_t pid =
        spawn(mpirun_args({std::string(GLINT_SOURCE_DIR) + "/scenes/features/animation.yaml",
                           "--width", "64", "--height", "48", "--frames", "0..2", "--rank-timeout",
                           "2", "-o", (dir_ / "out.#.exr").string()}),
              environment);
    ASSERT_GT(pid, 0);
    ASSERT_TRUE(ranks_hold(3)) << slurp(dir_ / "stderr.txt");  // each in its frame
    const pid_t victim = rank_process(pid, 2);
    ASSERT_GT(victim, 0);
    EXPECT_TRUE(signal_ends_job(pid, victim, SIGSTOP)) << "the job did not end in a minute";
    const std::string err = slurp(dir_ / "stderr.txt");
    EXPECT_NE(err.find("rank 2 ("), std::string::npos) << err;
    EXPECT_NE(err.find("while rendering frame 2"), std::string::npos) << err;
    EXPECT_FALSE(fs::exists(dir_ / "out.2.exr"));
    kill(victim, SIGCONT);
}

}  // namespace
}  // namespace glint
