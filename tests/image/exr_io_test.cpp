#include "glint/image/exr_io.h"

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfOutputFile.h>
#include <gtest/gtest.h>
#include <half.h>

#include <cstring>
#include <limits>
#include <string>
#include <vector>

#include "glint/image/image_error.h"
#include "glint/image/image_io.h"
#include "test_files.h"

namespace glint {
namespace {

bool same_bits(const Image& a, const Image& b) {
    return a.width == b.width && a.height == b.height && a.pixels.size() == b.pixels.size() &&
           std::memcmp(a.pixels.data(), b.pixels.data(), a.pixels.size() * sizeof(Color)) == 0;
}

TEST(Exr, RoundTripIsBitExact) {
    const auto path = testing::fresh_test_dir() / "exact.exr";
    Image image(7, 5);
    for (std::size_t i = 0; i < image.pixels.size(); ++i) {
        const float f = float(i);
        image.pixels[i] = {f / 7, -f * 1e-3f, f * f * 1e20f};
    }
    image.at(3, 2) = {std::numeric_limits<float>::infinity(),
                      std::numeric_limits<float>::denorm_min(), 65504.5f};
    write_exr(path, image);
    EXPECT_TRUE(same_bits(read_exr(path), image));
}

TEST(Exr, BytesInMemoryAreTheFilesBytesLayersIncluded) {
    const auto dir = testing::fresh_test_dir();
    Image image(33, 9), depth(33, 9);
    for (std::size_t i = 0; i < image.pixels.size(); ++i) {
        image.pixels[i] = {float(i) / 7, float(i % 5), -float(i)};
        depth.pixels[i] = {float(i) * 0.25f, 0, 0};
    }
    const ExrLayer layers[] = {{"depth", {"Z"}, &depth}};
    write_exr(dir / "file.exr", image, layers);
    EXPECT_EQ(exr_bytes(image, layers), testing::read_file(dir / "file.exr"));
    EXPECT_THROW(exr_bytes(Image(0, 3)), ImageError);
}

TEST(Exr, WritesFloatRgbWithZipCompression) {
    const auto path = testing::fresh_test_dir() / "layout.exr";
    write_exr(path, Image(4, 3, Color(1, 2, 3)));
    Imf::InputFile file(path.c_str());
    EXPECT_EQ(file.header().compression(), Imf::ZIP_COMPRESSION);
    std::vector<std::string> names;
    for (auto c = file.header().channels().begin(); c != file.header().channels().end(); ++c) {
        names.push_back(c.name());
        EXPECT_EQ(c.channel().type, Imf::FLOAT) << c.name();
    }
    EXPECT_EQ(names, (std::vector<std::string>{"B", "G", "R"}));  // OpenEXR sorts by name
    const Imath::Box2i window = file.header().dataWindow();
    EXPECT_EQ(window.min, Imath::V2i(0, 0));
    EXPECT_EQ(window.max, Imath::V2i(3, 2));
}

TEST(Exr, LayersAreWrittenAsNamedChannelsBesideTheImage) {
    const auto path = testing::fresh_test_dir() / "layers.exr";
    const Image image(3, 2, Color(1, 2, 3));
    Image depth(3, 2), normal(3, 2);
    for (std::size_t i = 0; i < 6; ++i) {
        depth.pixels[i] = Color::gray(float(i) + 0.25f);
        normal.pixels[i] = {0, -1, float(i)};
    }
    const ExrLayer layers[] = {{"depth", {"Z"}, &depth}, {"normal", {"X", "Y", "Z"}, &normal}};
    write_image(path, image, WriteOptions{.exr_layers = layers});

    Imf::InputFile file(path.c_str());
    std::vector<std::string> names;
    for (auto c = file.header().channels().begin(); c != file.header().channels().end(); ++c)
        names.push_back(c.name());
    EXPECT_EQ(names, (std::vector<std::string>{"B", "G", "R", "depth.Z", "normal.X", "normal.Y",
                                               "normal.Z"}));
    std::vector<float> z(6), ny(6);
    Imf::FrameBuffer frame;
    frame.insert("depth.Z", Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(z.data()), sizeof(float),
                                       3 * sizeof(float)));
    frame.insert("normal.Z", Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(ny.data()),
                                        sizeof(float), 3 * sizeof(float)));
    file.setFrameBuffer(frame);
    file.readPixels(0, 1);
    for (std::size_t i = 0; i < 6; ++i) {
        EXPECT_EQ(z[i], float(i) + 0.25f);
        EXPECT_EQ(ny[i], float(i));
    }
    EXPECT_TRUE(same_bits(read_exr(path), image));  // the image itself reads as before
}

TEST(Exr, OnlyAnExrFileTakesLayers) {
    const auto dir = testing::fresh_test_dir();
    const Image image(2, 2), depth(2, 2);
    const ExrLayer layers[] = {{"depth", {"Z"}, &depth}};
    EXPECT_THROW(write_image(dir / "a.png", image, WriteOptions{.exr_layers = layers}), ImageError);
    EXPECT_FALSE(std::filesystem::exists(dir / "a.png"));
    const Image small(1, 2);
    const ExrLayer wrong[] = {{"depth", {"Z"}, &small}};
    EXPECT_THROW(write_image(dir / "b.exr", image, WriteOptions{.exr_layers = wrong}), ImageError);
}

TEST(Exr, ReadsHalfChannelsAnOffsetDataWindowAndZeroForAMissingChannel) {
    const auto path = testing::fresh_test_dir() / "half.exr";
    const Imath::Box2i window(Imath::V2i(10, 20), Imath::V2i(12, 21));  // 3x2
    Imf::Header header(window, window);
    header.channels().insert("R", Imf::Channel(Imf::HALF));
    header.channels().insert("G", Imf::Channel(Imf::HALF));
    std::vector<Imath::half> red(6), green(6);
    for (int i = 0; i < 6; ++i) {
        red[i] = Imath::half(0.5f * float(i));
        green[i] = Imath::half(-2.0f + float(i));
    }
    Imf::FrameBuffer frame;
    frame.insert("R", Imf::Slice::Make(Imf::HALF, red.data(), window, sizeof(Imath::half),
                                       3 * sizeof(Imath::half)));
    frame.insert("G", Imf::Slice::Make(Imf::HALF, green.data(), window, sizeof(Imath::half),
                                       3 * sizeof(Imath::half)));
    {
        Imf::OutputFile file(path.c_str(), header);
        file.setFrameBuffer(frame);
        file.writePixels(2);
    }
    const Image image = read_exr(path);
    ASSERT_EQ(image.width, 3);
    ASSERT_EQ(image.height, 2);
    EXPECT_EQ(image.at(0, 0), Color(0, -2, 0));
    EXPECT_EQ(image.at(2, 1), Color(2.5f, 3, 0));
}

TEST(Exr, GarbageTruncatedAndMissingFilesAreErrors) {
    const auto dir = testing::fresh_test_dir();
    testing::expect_image_error([&] { read_exr(dir / "missing.exr"); }, dir / "missing.exr",
                                "cannot read EXR");

    testing::write_file(dir / "garbage.exr", "this is not an OpenEXR file, just some text");
    testing::expect_image_error([&] { read_exr(dir / "garbage.exr"); }, dir / "garbage.exr",
                                "cannot read EXR");
    testing::write_file(dir / "empty.exr", "");
    testing::expect_image_error([&] { read_exr(dir / "empty.exr"); }, dir / "empty.exr",
                                "cannot read EXR");

    Image image(64, 64);
    for (std::size_t i = 0; i < image.pixels.size(); ++i) image.pixels[i] = Color::gray(float(i));
    write_exr(dir / "good.exr", image);
    const std::string good = testing::read_file(dir / "good.exr");
    for (const std::size_t length : {std::size_t(20), good.size() / 2, good.size() - 3}) {
        SCOPED_TRACE(length);
        testing::write_file(dir / "truncated.exr", good.substr(0, length));
        testing::expect_image_error([&] { read_exr(dir / "truncated.exr"); }, dir / "truncated.exr",
                                    "cannot read EXR");
    }
}

TEST(Exr, WriteIntoAMissingFolderIsAnError) {
    const auto path = testing::fresh_test_dir() / "no" / "such" / "dir.exr";
    testing::expect_image_error([&] { write_exr(path, Image(1, 1)); }, path, "cannot write EXR");
}

}  // namespace
}  // namespace glint
