// Resume files: a state survives writing and reading exactly and continues to the image of an
// uninterrupted render; a file of another render, another version, or a damaged one is refused
// with a message that says why.
#include "glint/render/resume_file.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <bit>
#include <cstring>
#include <fstream>
#include <vector>

#include "glint/image/file_io.h"
#include "glint/render/render_output.h"
#include "glint/scene/yaml/yaml_scene_loader.h"

namespace glint {
namespace {

// Whether two arrays hold the same bytes; memcmp must not be given an empty one's null pointer.
template <class T>
bool same_bytes(const std::vector<T>& a, const std::vector<T>& b) {
    return a.size() == b.size() &&
           (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0);
}

namespace fs = std::filesystem;

class ResumeFile : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() / ("glint-resume-" + std::to_string(::getpid()));
        fs::create_directories(dir_);
        scene_file_ = dir_ / "scene.yaml";
        fs::copy_file(std::string(GLINT_SOURCE_DIR) + "/scenes/showcase.yaml", scene_file_,
                      fs::copy_options::overwrite_existing);
        scene_ = load_yaml_scene(scene_file_.string());
        scene_.settings.width = 24;
        scene_.settings.height = 18;
        scene_.settings.sampler = SamplerKind::jittered;
        scene_.settings.samples_per_pixel = 6;
        options_.seed = 7;
        options_.tile_size = 8;
        options_.pass_size = 2;
    }
    void TearDown() override { fs::remove_all(dir_); }

    RenderIdentity identity() const {
        return identify_render(scene_file_, {}, scene_.settings, options_, "1.2.3");
    }
    // A render stopped after its first pass, saved to `file`.
    RenderState save_stopped_render(const fs::path& file) const {
        RenderState state = initial_state(scene_.settings, options_);
        RenderProgress progress;
        progress.stop_after_pass = true;
        EXPECT_FALSE(render(World(scene_), options_, &progress, &state).complete);
        write_resume_file(file, identity(), state);
        return state;
    }
    // The message of the refusal to read `file` for `expected`.
    std::string refusal(const fs::path& file, const RenderIdentity& expected,
                        const RenderSettings& settings) const {
        try {
            read_resume_file(file, expected, settings);
        } catch (const ResumeError& e) {
            return e.what();
        }
        return "(read without complaint)";
    }

    fs::path dir_, scene_file_;
    Scene scene_;
    RenderOptions options_;
};

TEST_F(ResumeFile, StateSurvivesARoundTripExactlyAndContinuesToTheSameImage) {
    for (const std::optional<FilterSpec> filter :
         {std::optional<FilterSpec>{}, std::optional{FilterSpec{FilterKind::gaussian, 1.5f}}}) {
        scene_.settings.filter = filter;
        scene_.settings.adaptive = AdaptiveSampling{0.05f, 2};
        const fs::path file = dir_ / "image.png.resume";
        const RenderState saved = save_stopped_render(file);
        RenderState read = read_resume_file(file, identity(), scene_.settings);
        EXPECT_EQ(read.tile_passes, saved.tile_passes);
        EXPECT_EQ(read.samples, saved.samples);
        EXPECT_EQ(read.errors, saved.errors);
        EXPECT_EQ(read.rays, saved.rays);
        EXPECT_EQ(read.bad_samples.count, saved.bad_samples.count);
        EXPECT_TRUE(same_bytes(read.film.sums(), saved.film.sums()));
        EXPECT_TRUE(same_bytes(read.film.box_sums(), saved.film.box_sums()));

        const World world(scene_);
        const RenderResult continued = render(world, options_, nullptr, &read);
        const RenderResult whole = render(world, options_);
        EXPECT_TRUE(continued.complete);
        EXPECT_TRUE(continued.image.pixels == whole.image.pixels);
        EXPECT_EQ(continued.rays, whole.rays);
    }
}

TEST_F(ResumeFile, AnotherRenderIsRefusedNamingWhatDiffers) {
    const fs::path file = dir_ / "image.png.resume";
    save_stopped_render(file);
    const RenderSettings s = scene_.settings;
    const auto refused = [&](RenderSettings settings, RenderOptions options,
                             std::string version = "1.2.3") {
        return refusal(file, identify_render(scene_file_, {}, settings, options, version),
                       settings);
    };
    RenderOptions seed = options_;
    seed.seed = 3;
    EXPECT_NE(refused(s, seed).find("was written for seed 7, not 3"), std::string::npos)
        << refused(s, seed);
    EXPECT_NE(refused(s, options_, "1.3.0").find("written by glint 1.2.3, this is glint 1.3.0"),
              std::string::npos);
    RenderSettings wide = s;
    wide.width = 30;
    EXPECT_NE(refused(wide, options_).find("for an image of 24x18, not 30x18"), std::string::npos);
    RenderSettings more = s;
    more.samples_per_pixel = 8;
    EXPECT_NE(refused(more, options_).find("for 6 samples per pixel, not 8"), std::string::npos);
    RenderSettings distributed = s;
    distributed.integrator = IntegratorKind::distributed;
    EXPECT_NE(refused(distributed, options_).find("the whitted integrator, not distributed"),
              std::string::npos);
    RenderSettings gaussian = s;
    gaussian.filter = FilterSpec{FilterKind::gaussian, 1.5f};
    EXPECT_NE(refused(gaussian, options_).find("box filter of radius 0.5, not a gaussian"),
              std::string::npos)
        << refused(gaussian, options_);
    RenderSettings deeper = s;
    deeper.max_depth = 9;
    EXPECT_NE(refused(deeper, options_).find("max depth 8, not 9"), std::string::npos);
    RenderSettings adaptive = s;
    adaptive.adaptive = AdaptiveSampling{};
    EXPECT_NE(refused(adaptive, options_).find("no adaptive sampling, not adaptive"),
              std::string::npos);
    RenderOptions tiles = options_;
    tiles.tile_size = 16;
    EXPECT_NE(refused(s, tiles).find("tiles of 8 pixels, not 16"), std::string::npos);

    // The scene file edited since: the same path, other bytes.
    std::ofstream(scene_file_, std::ios::app) << "# edited\n";
    EXPECT_NE(refused(s, options_).find("another scene (its file has changed since)"),
              std::string::npos);
}

// A render of a scene that reads other files: a change to any of them, or another list of them,
// refuses the resume file, naming the file.
TEST_F(ResumeFile, AFileTheSceneReadIsCheckedForChangesToo) {
    const fs::path texture = dir_ / "wood.png", mesh = dir_ / "mesh.stl";
    std::ofstream(texture) << "texture bytes";
    std::ofstream(mesh) << "mesh bytes";
    const std::vector<fs::path> both = {texture, mesh};
    const auto refused = [&](const std::vector<fs::path>& files) {
        return refusal(dir_ / "image.png.resume",
                       identify_render(scene_file_, files, scene_.settings, options_, "1.2.3"),
                       scene_.settings);
    };
    RenderState state = initial_state(scene_.settings, options_);
    write_resume_file(dir_ / "image.png.resume",
                      identify_render(scene_file_, both, scene_.settings, options_, "1.2.3"),
                      state);
    EXPECT_EQ(refused(both), "(read without complaint)");
    EXPECT_NE(refused({texture}).find("was written for a scene that read " + mesh.string() +
                                      ", which this one does not"),
              std::string::npos)
        << refused({texture});
    EXPECT_NE(
        refused({texture, mesh, dir_ / "other.png"})
            .find("was written for a scene that did not read " + (dir_ / "other.png").string()),
        std::string::npos);
    std::ofstream(mesh) << "mesh bytes, edited";
    EXPECT_NE(refused(both).find("was written before " + mesh.string() + " changed"),
              std::string::npos)
        << refused(both);
    // The same size, other bytes.
    std::ofstream(mesh) << "mesh bytes";
    std::ofstream(texture) << "texture bytez";
    EXPECT_NE(refused(both).find("was written before " + texture.string() + " changed"),
              std::string::npos);
}

// A state of several mebibytes is packed and written piece by piece as it is encoded: every
// piece comes back, in order.
TEST_F(ResumeFile, AStateOfManyPiecesSurvivesARoundTripExactly) {
    scene_.settings.width = 300;
    scene_.settings.height = 200;
    scene_.settings.filter = FilterSpec{FilterKind::gaussian, 1.5f};
    scene_.settings.adaptive = AdaptiveSampling{0.05f, 2};
    RenderState saved = initial_state(scene_.settings, options_);
    std::uint64_t bits = 0x9e3779b97f4a7c15ull;  // noise, which does not pack
    const auto next = [&] { return bits = bits * 6364136223846793005ull + 1442695040888963407ull; };
    for (std::uint32_t& n : saved.samples) n = std::uint32_t(next() >> 40);
    for (PixelError& e : saved.errors) e = {int(next() >> 48), double(next()), double(next())};
    // Adaptive sampling's film holds each pixel's own samples: float sums.
    ASSERT_TRUE(saved.film.one_pixel());
    const auto noise = [&] { return std::bit_cast<float>(std::uint32_t(next() >> 33)); };
    for (BoxSum& b : saved.film.box_sums()) b = {{noise(), noise(), noise()}, noise()};
    std::fill(saved.tile_passes.begin(), saved.tile_passes.end(), 1);
    const fs::path file = dir_ / "image.png.resume";
    write_resume_file(file, identity(), saved);
    EXPECT_GT(fs::file_size(file), 2u << 20);  // several pieces, packed
    const RenderState read = read_resume_file(file, identity(), scene_.settings);
    EXPECT_EQ(read.samples, saved.samples);
    EXPECT_EQ(read.errors, saved.errors);
    EXPECT_TRUE(same_bytes(read.film.box_sums(), saved.film.box_sums()));
}

// A splatting film's fixed-point sums come back exactly too, the most negative and the largest.
TEST_F(ResumeFile, FixedPointSumsSurviveARoundTripExactly) {
    scene_.settings.width = 30;
    scene_.settings.height = 20;
    scene_.settings.filter = FilterSpec{FilterKind::gaussian, 1.5f};
    RenderState saved = initial_state(scene_.settings, options_);
    ASSERT_FALSE(saved.film.one_pixel());
    std::uint64_t bits = 0x9e3779b97f4a7c15ull;
    const auto next = [&] { return bits = bits * 6364136223846793005ull + 1442695040888963407ull; };
    for (PixelSum& p : saved.film.sums())
        p = {FixedSum(next()) << 40, FixedSum(next()), -FixedSum(next()), FixedSum(next())};
    saved.film.sums().front().r = -(FixedSum(1) << 126);
    saved.film.sums().back().g = (FixedSum(1) << 126) - 1 + (FixedSum(1) << 126);
    const fs::path file = dir_ / "image.png.resume";
    write_resume_file(file, identity(), saved);
    const RenderState read = read_resume_file(file, identity(), scene_.settings);
    EXPECT_TRUE(same_bytes(read.film.sums(), saved.film.sums()));
}

TEST_F(ResumeFile, MissingTruncatedCorruptAndForeignFilesAreRefused) {
    const fs::path file = dir_ / "image.png.resume";
    const RenderIdentity id = identity();
    EXPECT_NE(refusal(file, id, scene_.settings).find("there is no such file"), std::string::npos);
    save_stopped_render(file);
    const std::vector<unsigned char> bytes = read_whole_file(file);
    const auto write = [&](const std::vector<unsigned char>& b) {
        std::ofstream(file, std::ios::binary)
            .write(reinterpret_cast<const char*>(b.data()), std::streamsize(b.size()));
    };
    for (const std::size_t size : {bytes.size() / 2, bytes.size() - 1, std::size_t(40)}) {
        write({bytes.begin(), bytes.begin() + std::ptrdiff_t(size)});
        EXPECT_NE(refusal(file, id, scene_.settings).find("the file is truncated"),
                  std::string::npos)
            << size << " bytes: " << refusal(file, id, scene_.settings);
    }
    std::vector<unsigned char> flipped = bytes;
    flipped[bytes.size() - 10] ^= 0x40;
    write(flipped);
    EXPECT_NE(refusal(file, id, scene_.settings).find("the file is corrupt"), std::string::npos);
    std::vector<unsigned char> longer = bytes;
    longer.push_back(0);
    write(longer);
    EXPECT_NE(refusal(file, id, scene_.settings).find("the file is corrupt"), std::string::npos);
    write({'P', '6', '\n', '1', ' ', '1', '\n', '2', '5', '5', '\n', 0, 0, 0});
    EXPECT_NE(refusal(file, id, scene_.settings).find("not a glint resume file"),
              std::string::npos);
}

// A part's file is read without its scene, its part named; a resume of the whole refuses it;
// a damaged header cannot make the reader take the memory of a huge image.
TEST_F(ResumeFile, ASavedRenderIsReadWithoutItsSceneAndItsPartIsNamed) {
    const fs::path file = dir_ / "image.png.part2of3";
    const RenderPart part{2, 3, PartSplit::tiles};
    const RenderIdentity id =
        identify_render(scene_file_, {}, scene_.settings, options_, "1.2.3", part);
    const RenderState state = save_stopped_render(dir_ / "unused.resume");
    write_resume_file(file, id, state);
    const SavedRender saved = read_saved_render(file);
    EXPECT_EQ(saved.identity.part, part);
    EXPECT_EQ(identity_difference(saved.identity, id), "");
    EXPECT_EQ(saved.state.tile_passes, state.tile_passes);
    EXPECT_TRUE(same_bytes(saved.state.film.box_sums(), state.film.box_sums()));
    EXPECT_NE(refusal(file, identity(), scene_.settings)
                  .find("was written for part 2 of 3 (tiles), not the whole render"),
              std::string::npos);

    // The width and height follow the files' stamps in the header.
    std::size_t at = 8 + 4 + 4 + id.glint_version.size() + 4 + id.scene_path.size() + 4;
    for (const FileStamp& f : id.files) at += 4 + f.path.size() + 8 + 4 + 1;
    std::vector<unsigned char> bytes = read_whole_file(file);
    for (const std::size_t field : {at, at + 4}) {
        const std::uint32_t huge = 60000;
        std::memcpy(&bytes[field], &huge, 4);  // little-endian, as the file
    }
    std::ofstream(file, std::ios::binary)
        .write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
    try {
        read_saved_render(file);
        ADD_FAILURE() << "a 60000 x 60000 image in a small file was read";
    } catch (const ResumeError& e) {
        EXPECT_NE(std::string(e.what()).find("the file is corrupt"), std::string::npos) << e.what();
    }
}

TEST(ResumePath, IsTheOutputWithResumeAppended) {
    EXPECT_EQ(resume_path("out/image.png"), std::filesystem::path("out/image.png.resume"));
}

}  // namespace
}  // namespace glint

namespace glint {
namespace {

// A checkpoint at every pass but the last: the files hold the render as it was after the one
// before the last, and a render continued from them gives the uninterrupted image.
TEST_F(ResumeFile, CheckpointsSaveEachPassButTheLastAndContinueToTheSameImage) {
    const World world(scene_);
    const fs::path partial = dir_ / "image.partial.png", resume = dir_ / "image.png.resume";
    RenderOptions options = options_;
    options.after_pass = checkpoint_hook({partial, resume, identity(), {}, false});
    const RenderResult whole = render(world, options);
    ASSERT_TRUE(fs::exists(partial));
    RenderState saved = read_resume_file(resume, identity(), scene_.settings);
    EXPECT_EQ(saved.passes_done(), 2);  // 6 samples in passes of 2
    const RenderResult continued = render(world, options_, nullptr, &saved);
    EXPECT_EQ(continued.image.pixels, whole.image.pixels);
}

// With an interval longer than the render, nothing is saved.
TEST_F(ResumeFile, NoCheckpointBeforeItsInterval) {
    const fs::path partial = dir_ / "image.partial.png", resume = dir_ / "image.png.resume";
    RenderOptions options = options_;
    options.after_pass =
        checkpoint_hook({partial, resume, identity(), std::chrono::hours(1), false});
    render(World(scene_), options);
    EXPECT_FALSE(fs::exists(partial));
    EXPECT_FALSE(fs::exists(resume));
}

}  // namespace
}  // namespace glint
