#include "glint/image/image_format.h"

#include <gtest/gtest.h>

#include <string>

namespace glint {
namespace {

TEST(ImageFormat, ExtensionPicksTheFormatIgnoringCase) {
    EXPECT_EQ(format_from_extension("out.png"), ImageFormat::png);
    EXPECT_EQ(format_from_extension("dir.exr/OUT.PNG"), ImageFormat::png);
    EXPECT_EQ(format_from_extension("a.b.Ppm"), ImageFormat::ppm);
    EXPECT_EQ(format_from_extension("/tmp/x.pfm"), ImageFormat::pfm);
    EXPECT_EQ(format_from_extension("render.eXr"), ImageFormat::exr);
}

TEST(ImageFormat, UnknownOrMissingExtensionIsNothing) {
    EXPECT_EQ(format_from_extension("out.xyz"), std::nullopt);
    EXPECT_EQ(format_from_extension("out.png.gz"), std::nullopt);
    EXPECT_EQ(format_from_extension("png"), std::nullopt);
    EXPECT_EQ(format_from_extension(".png"), std::nullopt);  // a hidden file named "png"
    EXPECT_EQ(format_from_extension(""), std::nullopt);
}

TEST(ImageFormat, ExtensionsAndTheirList) {
    EXPECT_EQ(extension_of(ImageFormat::png), ".png");
    EXPECT_EQ(extension_of(ImageFormat::exr), ".exr");
    EXPECT_EQ(known_image_extensions(), ".png, .ppm, .pfm, .exr");
    for (const auto format :
         {ImageFormat::png, ImageFormat::ppm, ImageFormat::pfm, ImageFormat::exr}) {
        std::string name = "x";
        name += extension_of(format);
        EXPECT_EQ(format_from_extension(name), format);
    }
}

}  // namespace
}  // namespace glint
