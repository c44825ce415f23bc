#include "glint/image/image_io.h"

#include <gtest/gtest.h>
#include <sys/resource.h>

#include <algorithm>
#include <csignal>
#include <string>
#include <vector>

#include "glint/image/image_error.h"
#include "test_files.h"

namespace glint {
namespace {

using Names = std::vector<std::string>;

Image test_image() {
    Image image(3, 2);
    for (int y = 0; y < 2; ++y) {
        for (int x = 0; x < 3; ++x) image.at(x, y) = {float(x) / 2, float(y), 0.25f};
    }
    return image;
}

TEST(ImageIo, ExtensionPicksTheFormatIgnoringCase) {
    const auto dir = testing::fresh_test_dir();
    const Image image = test_image();
    const std::pair<const char*, std::string> cases[] = {
        {"a.PNG", "\x89PNG"}, {"b.ppm", "P6\n"}, {"c.Pfm", "PF\n"}, {"d.exr", "\x76\x2f\x31\x01"}};
    for (const auto& [name, magic] : cases) {
        SCOPED_TRACE(name);
        write_image(dir / name, image);
        EXPECT_EQ(testing::read_file(dir / name).substr(0, magic.size()), magic);
        const Image back = read_image(dir / name);
        ASSERT_EQ(back.width, 3);
        ASSERT_EQ(back.height, 2);
        EXPECT_EQ(back.at(2, 1).r, 1);
        EXPECT_EQ(back.at(2, 1).g, 1);
        EXPECT_NEAR(back.at(2, 1).b, 0.25f, 0.01f);
    }
    EXPECT_EQ(testing::file_names_in(dir).size(), 4u);  // no temporaries left behind
}

TEST(ImageIo, FloatFormatsAreExactAndPpmAsciiIsAnOption) {
    const auto dir = testing::fresh_test_dir();
    const Image image = test_image();
    write_image(dir / "a.pfm", image);
    write_image(dir / "a.exr", image);
    EXPECT_EQ(read_image(dir / "a.pfm").pixels, image.pixels);
    EXPECT_EQ(read_image(dir / "a.exr").pixels, image.pixels);
    write_image(dir / "a.ppm", image, {.ppm_ascii = true});
    EXPECT_EQ(testing::read_file(dir / "a.ppm").substr(0, 3), "P3\n");
}

TEST(ImageIo, ReplacesAnExistingFile) {
    const auto path = testing::fresh_test_dir() / "out.pfm";
    testing::write_file(path, "old contents");
    write_image(path, test_image());
    EXPECT_EQ(read_image(path).pixels, test_image().pixels);
}

TEST(ImageIo, UnknownExtensionNamesTheFileAndTheChoices) {
    const auto dir = testing::fresh_test_dir();
    try {
        write_image(dir / "out.xyz", test_image());
        FAIL() << "expected an ImageError";
    } catch (const ImageError& e) {
        EXPECT_EQ(std::string(e.what()),
                  (dir / "out.xyz").string() +
                      ": unknown image format \".xyz\"; known formats are .png, .ppm, .pfm, .exr");
    }
    testing::expect_image_error([&] { write_image(dir / "out", test_image()); }, dir / "out",
                                "no file extension to tell the image format; known formats are");
    testing::expect_image_error([&] { read_image(dir / "in.jpg"); }, dir / "in.jpg",
                                "unknown image format \".jpg\"");
    EXPECT_TRUE(testing::file_names_in(dir).empty());
}

TEST(ImageIo, RejectsEmptyAndInconsistentImagesWithoutTouchingTheTarget) {
    const auto dir = testing::fresh_test_dir();
    const auto path = dir / "out.png";
    testing::write_file(path, "old");
    Image empty;
    testing::expect_image_error([&] { write_image(path, empty); }, path, "0x0 is empty");
    Image negative;
    negative.width = -1;
    negative.height = 2;
    testing::expect_image_error([&] { write_image(path, negative); }, path, "-1x2");
    Image short_of_pixels(2, 2);
    short_of_pixels.pixels.resize(3);
    testing::expect_image_error([&] { write_image(path, short_of_pixels); }, path,
                                "image claims 2x2 pixels but holds 3");
    EXPECT_EQ(testing::read_file(path), "old");
    EXPECT_EQ(testing::file_names_in(dir), Names{"out.png"});
}

TEST(ImageIo, WriteErrorsNameTheTargetNotTheTemporary) {
    const auto dir = testing::fresh_test_dir();
    for (const char* name : {"out.png", "out.ppm", "out.pfm", "out.exr"}) {
        SCOPED_TRACE(name);
        const auto path = dir / "missing" / name;
        try {
            write_image(path, test_image());
            ADD_FAILURE() << "expected an ImageError";
        } catch (const ImageError& e) {
            EXPECT_EQ(e.file, path);
            EXPECT_EQ(std::string(e.what()).find(".tmp-"), std::string::npos) << e.what();
        }
    }
}

// Lowers this process's file-size limit for one test, as `ulimit -f` does, with SIGXFSZ ignored
// (as glint's tool does) so that writes beyond the limit fail with EFBIG: a full disk that
// needs no special file system.
class FileSizeLimit {
public:
    explicit FileSizeLimit(rlim_t bytes) {
        getrlimit(RLIMIT_FSIZE, &previous_);
        rlimit lowered = previous_;
        lowered.rlim_cur = bytes;
        setrlimit(RLIMIT_FSIZE, &lowered);
        previous_handler_ = std::signal(SIGXFSZ, SIG_IGN);
    }
    ~FileSizeLimit() {
        setrlimit(RLIMIT_FSIZE, &previous_);
        std::signal(SIGXFSZ, previous_handler_);
    }
    FileSizeLimit(const FileSizeLimit&) = delete;
    FileSizeLimit& operator=(const FileSizeLimit&) = delete;

private:
    rlimit previous_{};
    void (*previous_handler_)(int) = SIG_DFL;
};

TEST(ImageIo, AFullDiskLeavesThePreviousFileAndNoTemporary) {
    const auto dir = testing::fresh_test_dir();
    // 64 x 64 pixels of noise: no format compresses them below the limit of 4 KiB.
    Image noise(64, 64);
    unsigned state = 12345;
    for (Color& c : noise.pixels) {
        const auto next = [&] {
            return float((state = state * 1664525u + 1013904223u) >> 8) / 0x1p24f;
        };
        c = {next(), next(), next()};
    }
    for (const char* name : {"out.png", "out.ppm", "out.pfm", "out.exr"}) {
        SCOPED_TRACE(name);
        const auto path = dir / name;
        testing::write_file(path, "the previous image");
        {
            const FileSizeLimit limit(4096);
            testing::expect_image_error([&] { write_image(path, noise); }, path, "File too large");
        }
        EXPECT_EQ(testing::read_file(path), "the previous image");
    }
    Names names = testing::file_names_in(dir);
    std::sort(names.begin(), names.end());
    EXPECT_EQ(names, (Names{"out.exr", "out.pfm", "out.png", "out.ppm"}));
}

TEST(ImageIo, ReadErrorsNameTheFile) {
    const auto dir = testing::fresh_test_dir();
    for (const char* name : {"in.png", "in.ppm", "in.pfm", "in.exr"}) {
        SCOPED_TRACE(name);
        testing::write_file(dir / name, "junk");
        testing::expect_image_error([&] { read_image(dir / name); }, dir / name, "");
    }
}

}  // namespace
}  // namespace glint
