#include "glint/image/netpbm_tokenizer.h"

#include <gtest/gtest.h>

#include <string>
#include <string_view>

#include "test_files.h"

namespace glint {
namespace {

std::span<const unsigned char> bytes_of(std::string_view s) {
    return {reinterpret_cast<const unsigned char*>(s.data()), s.size()};
}

TEST(PpmTokenizer, SplitsOnWhitespaceAndSkipsComments) {
    const std::string text = "P3\n# a comment 1 2 3\n 2\t1#no space before\r\n255\nrest";
    NetpbmTokenizer tokens(bytes_of(text), "t.ppm", "PPM", true);
    EXPECT_EQ(tokens.next_token(), "P3");
    EXPECT_EQ(tokens.next_token(), "2");
    EXPECT_EQ(tokens.next_token(), "1");
    EXPECT_EQ(tokens.next_token(), "255");
    EXPECT_EQ(tokens.raster_start(), text.find("rest"));
    EXPECT_EQ(tokens.next_token(), "rest");
    EXPECT_EQ(tokens.next_token(), "");
    EXPECT_EQ(tokens.raster_start(), std::nullopt);
}

TEST(PfmTokenizer, WithoutCommentsAHashIsPartOfAToken) {
    const std::string text = "PF #1";
    NetpbmTokenizer tokens(bytes_of(text), "t.pfm", "PFM", false);
    EXPECT_EQ(tokens.next_token(), "PF");
    EXPECT_EQ(tokens.next_token(), "#1");
}

TEST(PpmTokenizer, PositiveNumbersAndTheirErrors) {
    const std::string text = "12 0 -3 7x 99999999999999999999";
    NetpbmTokenizer tokens(bytes_of(text), "t.ppm", "PPM", true);
    EXPECT_EQ(tokens.next_positive("width", 100), 12);
    testing::expect_image_error([&] { tokens.next_positive("width", 100); }, "t.ppm",
                                "malformed PPM: width must be an integer from 1 to 100, got \"0\"");
    testing::expect_image_error([&] { tokens.next_positive("height", 100); }, "t.ppm",
                                "got \"-3\"");
    testing::expect_image_error([&] { tokens.next_positive("maxval", 100); }, "t.ppm",
                                "got \"7x\"");
    testing::expect_image_error([&] { tokens.next_positive("maxval", 100); }, "t.ppm",
                                "got \"9999999999999999...\"");
    testing::expect_image_error([&] { tokens.next_positive("maxval", 100); }, "t.ppm",
                                "header ends before the maxval");
}

TEST(PpmTokenizer, ParseDecimal) {
    EXPECT_EQ(parse_decimal("0", 10), 0);
    EXPECT_EQ(parse_decimal("010", 10), 10);
    EXPECT_EQ(parse_decimal("11", 10), std::nullopt);
    EXPECT_EQ(parse_decimal("+1", 10), std::nullopt);
    EXPECT_EQ(parse_decimal("", 10), std::nullopt);
    EXPECT_EQ(quote_header_token("a\x01z"), "\"a?z\"");
}

}  // namespace
}  // namespace glint
