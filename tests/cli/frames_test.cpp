// `glint render` of an animated scene: each frame is the image of the still at the frame's
// moment, bit for bit; --frames picks them; a stopped sequence resumes at the frame in flight.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "cli_fixture.h"

namespace glint {
namespace {

// Shapes, camera and lights all move; the shutter stays open half a frame.
std::string animated_scene(const std::string& animation, const std::string& shutter) {
    return "image: {width: 48, height: 32, integrator: distributed, samples: 8}\n" + animation +
           R"(
camera:
  from: [0, 2, -8]
  at: [0, 1, 0]
  shutter: )" +
           shutter +
           R"(
  motion: [{time: 0, from: [-2, 2, -8]}, {time: 1, from: [2, 2, -8]}]
lights:
  - type: point
    position: [-3, 5, -3]
    motion: [{time: 0}, {time: 1, transform: [{translate: [6, 0, 0]}]}]
  - type: sphere
    center: [0, 4, 0]
    radius: 0.3
    motion: [{time: 0}, {time: 1, transform: [{translate: [0, 0, 3]}]}]
objects:
  - {type: plane, point: [0, 0, 0], normal: [0, 1, 0]}
  - type: sphere
    center: [-1, 0.5, 0]
    radius: 0.5
    motion: [{time: 0}, {time: 1, transform: [{translate: [2, 1, 0]}]}]
)";
}

class Frames : public Cli {
protected:
    void SetUp() override {
        Cli::SetUp();
        write_scene("anim.yaml", animated_scene("animation: {frames: 4, fps: 8}", "[0, 0.0625]"));
    }
    // Frame f's still: the shutter at f / 8 seconds, 1/16 long (exact in binary).
    std::string still_of_frame(int f) const {
        const std::string open = std::to_string(f / 8.0), close = std::to_string(f / 8.0 + 0.0625);
        write_scene("still.yaml", animated_scene("", "[" + open + ", " + close + "]"));
        const Outcome still = run_glint("render still.yaml -q --seed 5 -o still.pfm");
        EXPECT_EQ(still.exit_code, 0) << still.err;
        return slurp(dir_ / "still.pfm");
    }
};

TEST_F(Frames, EachFrameIsTheStillAtItsMoment) {
    const Outcome sequence = run_glint("render anim.yaml --seed 5 -o 'seq.#.pfm'");
    ASSERT_EQ(sequence.exit_code, 0) << sequence.err;
    EXPECT_NE(sequence.out.find("glint: wrote seq.3.pfm (frame 3;"), std::string::npos)
        << sequence.out;
    for (int f = 0; f < 4; ++f) {
        SCOPED_TRACE(f);
        const std::string frame = slurp(dir_ / ("seq." + std::to_string(f) + ".pfm"));
        ASSERT_FALSE(frame.empty());
        EXPECT_TRUE(frame == still_of_frame(f));
        if (f > 0) {
            EXPECT_FALSE(frame == slurp(dir_ / ("seq." + std::to_string(f - 1) + ".pfm")));
        }
    }
}

TEST_F(Frames, FramesPicksTheRangeAndTheDefaultOutputNumbersThem) {
    const Outcome some = run_glint("render anim.yaml -q --seed 5 --frames 1..2 -o 'out.###.pfm'");
    ASSERT_EQ(some.exit_code, 0) << some.err;
    EXPECT_FALSE(fs::exists(dir_ / "out.000.pfm"));
    EXPECT_TRUE(slurp(dir_ / "out.002.pfm") == still_of_frame(2));
    EXPECT_FALSE(fs::exists(dir_ / "out.003.pfm"));
    const Outcome one = run_glint("render anim.yaml -q --frames 3 --width 8 --height 8");
    ASSERT_EQ(one.exit_code, 0) << one.err;
    EXPECT_TRUE(fs::exists(dir_ / "anim.0003.png"));
    EXPECT_FALSE(fs::exists(dir_ / "anim.0002.png"));
    // Without # in the output, frame 0 as a still, and a note saying so.
    const Outcome first = run_glint("render anim.yaml --seed 5 -o first.pfm");
    ASSERT_EQ(first.exit_code, 0) << first.err;
    EXPECT_NE(first.err.find("an animation of 4 frames: this renders frame 0"), std::string::npos)
        << first.err;
    EXPECT_TRUE(slurp(dir_ / "first.pfm") == still_of_frame(0));
}

TEST_F(Frames, AStoppedSequenceResumesAtTheFrameInFlight) {
    ASSERT_EQ(run_glint("render anim.yaml -q --seed 5 -o 'whole.#.pfm'").exit_code, 0);
    ASSERT_EQ(run_glint("render anim.yaml -q --seed 5 --frames 0 -o 'seq.#.pfm'").exit_code, 0);
    // Frame 0 is done; frame 1 is held after its first tile and stopped by SIGINT.
    const pid_t pid = spawn_glint({"render", (dir_ / "anim.yaml").string(), "--seed", "5", "-o",
                                   (dir_ / "seq.#.pfm").string(), "--resume"},
                                  hold_after(1));
    ASSERT_GT(pid, 0);
    const Outcome stopped = stop_when_held(pid);
    const std::string& err = stopped.err;
    ASSERT_EQ(stopped.exit_code, 130) << err;
    EXPECT_NE(err.find("glint: frame 0 is done"), std::string::npos) << err;
    EXPECT_NE(err.find("--frames 1..3 --resume"), std::string::npos) << err;
    EXPECT_TRUE(fs::exists(dir_ / "seq.1.pfm.resume"));
    EXPECT_FALSE(fs::exists(dir_ / "seq.1.pfm"));

    const Outcome resumed = run_glint("render anim.yaml -q --seed 5 -o 'seq.#.pfm' --resume");
    ASSERT_EQ(resumed.exit_code, 0) << resumed.err;
    for (int f = 0; f < 4; ++f) {
        const std::string n = std::to_string(f);
        EXPECT_TRUE(slurp(dir_ / ("seq." + n + ".pfm")) == slurp(dir_ / ("whole." + n + ".pfm")))
            << f;
        EXPECT_FALSE(fs::exists(dir_ / ("seq." + n + ".pfm.resume")));
    }
}

TEST_F(Frames, ExplainShowsAFramesSampleAsTheStillsAtItsMoment) {
    const std::string sample = " --pixel 20,12 --sample 3 --seed 5 --format json";
    const Outcome frame = run_glint("explain anim.yaml --frame 2" + sample);
    ASSERT_EQ(frame.exit_code, 0) << frame.err;
    still_of_frame(2);
    const Outcome still = run_glint("explain still.yaml" + sample);
    ASSERT_EQ(still.exit_code, 0) << still.err;
    EXPECT_EQ(frame.out, still.out);
    EXPECT_NE(frame.out, run_glint("explain anim.yaml" + sample).out);
    const Outcome past = run_glint("explain anim.yaml --frame 4" + sample);
    EXPECT_EQ(past.exit_code, 2);
    EXPECT_NE(past.err.find("--frame: the scene's animation has frames 0..3"), std::string::npos)
        << past.err;
    const Outcome of_still = run_glint("explain still.yaml --frame 1" + sample);
    EXPECT_EQ(of_still.exit_code, 2);
    EXPECT_NE(of_still.err.find("--frame: the scene is a still"), std::string::npos)
        << of_still.err;
}

TEST_F(Frames, BadFrameOptionsAreUsageErrors) {
    write_scene("still.yaml", animated_scene("", "[0, 0]"));
    const struct {
        std::string args, error;
    } cases[] = {
        {"still.yaml --frames 0..1 -o 'x.#.png'", "--frames: the scene is a still"},
        {"still.yaml -o 'x.#.png'", "names frames with '#', but the scene is a still"},
        {"anim.yaml --frames 2..9 -o 'x.#.png'", "the scene's animation has frames 0..3"},
        {"anim.yaml --frames 2..1 -o 'x.#.png'", "--frames: expected A..B"},
        {"anim.yaml --frames two -o 'x.#.png'", "--frames: expected A..B"},
        {"anim.yaml --frames 1..2 -o x.png", "must name where each frame's number goes"},
        {"anim.yaml -o 'x.#.png' --stats s.json", "--stats: a sequence writes one file a frame"},
        {"anim.yaml -o 'x.#.png' --part 1/2", "--part renders a part of one image"},
        {"anim.yaml -o 'nowhere/x.#.png'", "nowhere"},
    };
    for (const auto& c : cases) {
        const Outcome bad = run_glint("render " + c.args);
        EXPECT_EQ(bad.exit_code, 2) << c.args;
        EXPECT_NE(bad.err.find(c.error), std::string::npos) << c.args << "\n" << bad.err;
    }
    EXPECT_FALSE(fs::exists(dir_ / "x.0.png"));
}

}  // namespace
}  // namespace glint
