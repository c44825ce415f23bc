// `glint render --part I/N` and `glint merge`: parts rendered one by one merge into the image one
// run writes, bit for bit; a stopped part resumes; merge names what keeps parts from merging.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "cli_fixture.h"

namespace glint {
namespace {

class Parts : public Cli {
protected:
    // The distributed showcase, small, with `more` options: a Gaussian across tiles.
    static std::string render(const std::string& more, int seed = 3) {
        return "render " + scene("distributed-showcase.yaml") +
               " --width 64 --height 40 --spp 32 -q --seed " + std::to_string(seed) + " " + more;
    }
    // Renders every part of `count`, split by `split`, to out.exr's parts.
    void render_parts(int count, const std::string& split) const {
        for (int i = 1; i <= count; ++i) {
            const Outcome part = run_glint(render("-o out.exr --part " + std::to_string(i) + "/" +
                                                  std::to_string(count) + " --split " + split));
            ASSERT_EQ(part.exit_code, 0) << part.err;
        }
    }
};

TEST_F(Parts, TilePartsAndPassPartsMergeIntoTheImageOfOneRun) {
    ASSERT_EQ(run_glint(render("-o whole.exr")).exit_code, 0);
    // 12 tiles in 3 parts; 2 passes of 16 samples in 2.
    for (const std::string split : {"tiles", "passes"}) {
        SCOPED_TRACE(split);
        const int count = split == "tiles" ? 3 : 2;
        render_parts(count, split);
        const std::string n = std::to_string(count);
        EXPECT_TRUE(fs::exists(dir_ / ("out.exr.part2of" + n)));
        EXPECT_FALSE(fs::exists(dir_ / "out.exr"));
        std::string parts;
        for (int i = count; i >= 1; --i) parts += " out.exr.part" + std::to_string(i) + "of" + n;
        const Outcome merged = run_glint("merge" + parts);
        ASSERT_EQ(merged.exit_code, 0) << merged.err;
        EXPECT_NE(merged.out.find("glint: wrote out.exr (from " + n + " parts by " + split),
                  std::string::npos)
            << merged.out;
        EXPECT_TRUE(slurp(dir_ / "out.exr") == slurp(dir_ / "whole.exr"));
        fs::remove(dir_ / "out.exr");
        if (split == "tiles") render_parts(3, "tiles");  // for the PNG below
    }
    // Any image format, named with -o.
    ASSERT_EQ(run_glint(render("-o whole.png")).exit_code, 0);
    ASSERT_EQ(
        run_glint("merge -q out.exr.part1of3 out.exr.part2of3 out.exr.part3of3 -o m.png").exit_code,
        0);
    EXPECT_TRUE(slurp(dir_ / "m.png") == slurp(dir_ / "whole.png"));
}

TEST_F(Parts, AStoppedPartResumesToTheSamePart) {
    ASSERT_EQ(run_glint(render("-o whole.exr")).exit_code, 0);
    render_parts(2, "tiles");
    fs::remove(dir_ / "out.exr.part1of2");
    // Held after its first tile and stopped by SIGINT.
    std::vector<std::string> args = {
        "render",   GLINT_SOURCE_DIR "/scenes/distributed-showcase.yaml",
        "--width",  "64",
        "--height", "40",
        "--spp",    "32",
        "--seed",   "3",
        "-q",       "-o",
        "out.exr",  "--part",
        "1/2"};
    for (std::string& a : args)
        if (a == "out.exr") a = (dir_ / "out.exr").string();
    const pid_t pid = spawn_glint(args, hold_after(1));
    ASSERT_GT(pid, 0);
    const Outcome stopped = stop_when_held(pid);
    const std::string& err = stopped.err;
    ASSERT_EQ(stopped.exit_code, 130) << err;
    EXPECT_NE(err.find("part 1 of 2 (tiles) of"), std::string::npos) << err;
    EXPECT_NE(err.find("--part 1/2 --resume"), std::string::npos) << err;
    EXPECT_TRUE(fs::exists(dir_ / "out.exr.part1of2.resume"));
    EXPECT_FALSE(fs::exists(dir_ / "out.exr.part1of2"));
    EXPECT_FALSE(fs::exists(dir_ / "out.partial.exr"));  // a part's image alone is no use

    const Outcome merged_early =
        run_glint("merge out.exr.part1of2.resume out.exr.part2of2 -o x.exr");
    EXPECT_EQ(merged_early.exit_code, 2);
    EXPECT_NE(merged_early.err.find("is part 1 of 2 (tiles), unfinished"), std::string::npos)
        << merged_early.err;

    const Outcome resumed = run_glint(render("-o out.exr --part 1/2 --resume"));
    ASSERT_EQ(resumed.exit_code, 0) << resumed.err;
    EXPECT_FALSE(fs::exists(dir_ / "out.exr.part1of2.resume"));
    ASSERT_EQ(run_glint("merge out.exr.part1of2 out.exr.part2of2").exit_code, 0);
    EXPECT_TRUE(slurp(dir_ / "out.exr") == slurp(dir_ / "whole.exr"));
}

TEST_F(Parts, MergeNamesWhatKeepsThePartsApart) {
    render_parts(3, "tiles");
    ASSERT_EQ(run_glint(render("-o seed.exr --part 2/3", 4)).exit_code, 0);
    ASSERT_EQ(run_glint(render("-o path.exr --part 2/3 --integrator path")).exit_code, 0);
    ASSERT_EQ(run_glint(render("-o passes.exr --part 2/2 --split passes")).exit_code, 0);
    ASSERT_EQ(run_glint(render("-o four.exr --part 2/4")).exit_code, 0);
    std::ofstream(dir_ / "junk.exr.part2of3") << "not a part";
    const std::string p1 = "out.exr.part1of3", p3 = "out.exr.part3of3";
    struct Refused {
        std::string parts, message;
    };
    for (const Refused& r : std::vector<Refused>{
             {"seed.exr.part2of3",
              "\"seed.exr.part2of3\" with \"out.exr.part1of3\": it was "
              "written for seed 4, not 3"},
             {"path.exr.part2of3", "written for the path integrator, not distributed"},
             {"passes.exr.part2of2",
              "it is part 2 of 2 (passes), and that part 1 of 3 (tiles): the parts of one "
              "render are split alike"},
             {"four.exr.part2of4", "part 2 of 4 (tiles)"},
             {"junk.exr.part2of3", "cannot read \"junk.exr.part2of3\": not a glint part or resume"},
             {"missing.exr.part2of3",
              "cannot read \"missing.exr.part2of3\": there is no such file"},
             {"", "part 2 of 3 (tiles) is missing (2 of 3 parts given)"},
             {p1, "\"out.exr.part1of3\" and \"out.exr.part1of3\" are both part 1 of 3 (tiles)"}}) {
        SCOPED_TRACE(r.parts);
        const Outcome o = run_glint("merge " + p1 + " " + r.parts + " " + p3 + " -o m.exr");
        EXPECT_EQ(o.exit_code, 2);
        EXPECT_NE(o.err.find(r.message), std::string::npos) << o.err;
        EXPECT_FALSE(fs::exists(dir_ / "m.exr"));
    }
    const Outcome unnamed = run_glint("merge seed.exr.part2of3.x");
    EXPECT_EQ(unnamed.exit_code, 2);
    EXPECT_NE(unnamed.err.find("give it with -o"), std::string::npos) << unnamed.err;
}

TEST_F(Parts, BadPartOptionsAreUsageErrors) {
    struct Refused {
        std::string options, message;
    };
    for (const Refused& r : std::vector<Refused>{
             {"--part 0/3", "--part: expected I/N, part I of N parts with 1 <= I <= N"},
             {"--part 4/3", "expected I/N"},
             {"--part three", "expected I/N"},
             {"--part 1/2 --split rows", "--split"},
             {"--part 1/200", "the image has 12 tiles, too few for 200 parts"},
             {"--part 1/3 --split passes", "the render has 2 passes of 16 samples, too few"},
             {"--part 1/2 --aov depth",
              "--aov cannot be combined with --resume, --checkpoint or "
              "--part"},
             {"--part 1/2 --samples-image s.png", "--samples-image cannot be combined with --part"},
             {"--part 1/2 --resume", "cannot resume from"}}) {
        SCOPED_TRACE(r.options);
        const Outcome o = run_glint(render("-o out.exr " + r.options));
        EXPECT_EQ(o.exit_code, 2);
        EXPECT_NE(o.err.find(r.message), std::string::npos) << o.err;
        EXPECT_FALSE(fs::exists(dir_ / "out.exr.part1of2"));
    }
    const Outcome adaptive = run_glint("render " + scene("features/adaptive.yaml") +
                                       " -q -o a.exr --part 1/2 --split passes");
    EXPECT_EQ(adaptive.exit_code, 2);
    EXPECT_NE(adaptive.err.find("adaptive sampling decides each pass from the passes before it"),
              std::string::npos)
        << adaptive.err;
}

}  // namespace
}  // namespace glint
