// The NFF tokenizer: tokens with their line and column, comments, numbers in every form C's %g
// writes, and where errors point.
#include "glint/scene/nff/nff_tokenizer.h"

#include <gtest/gtest.h>

#include <bit>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <string>
#include <vector>

namespace glint {
namespace {

const NffEntity kSphere{"sphere", {}};

TEST(NffTokenizer, TokensKnowTheirLineAndColumn) {
    NffTokenizer tokens("v\n  from 1 2#c\n\n# whole line\r\n\tat\n", "t.nff");
    const auto expect = [&](std::string_view text, std::uint32_t line, std::uint32_t column) {
        const NffToken t = tokens.next();
        EXPECT_EQ(t.text, text);
        EXPECT_EQ(t.line, line) << text;
        EXPECT_EQ(t.column, column) << text;
    };
    expect("v", 1, 1);
    expect("from", 2, 3);
    expect("1", 2, 8);
    expect("2", 2, 10);  // the comment ends the token
    expect("at", 5, 2);
    EXPECT_TRUE(tokens.next().at_end());
    EXPECT_TRUE(tokens.next().at_end());
}

TEST(NffTokenizer, PeekDoesNotConsume) {
    NffTokenizer tokens("  l 1", "t.nff");
    EXPECT_EQ(tokens.peek().text, "l");
    EXPECT_EQ(tokens.peek().column, 3u);
    EXPECT_EQ(tokens.next().text, "l");
    EXPECT_EQ(tokens.next().text, "1");
    EXPECT_TRUE(tokens.peek().at_end());
}

TEST(NffTokenizer, NumbersInEveryFormOfPercentG) {
    NffTokenizer tokens("0.704769 -2.55836e-17 1e+06 -0 +3 .5 7. 1E2 3.4028235e38 1e-46", "t.nff");
    const NffField f{"radius"};
    EXPECT_EQ(tokens.number(kSphere, f), 0.704769f);
    EXPECT_EQ(tokens.number(kSphere, f), -2.55836e-17f);
    EXPECT_EQ(tokens.number(kSphere, f), 1e6f);
    const float negative_zero = tokens.number(kSphere, f);
    EXPECT_EQ(negative_zero, 0);
    EXPECT_TRUE(std::signbit(negative_zero));
    EXPECT_EQ(tokens.number(kSphere, f), 3);
    EXPECT_EQ(tokens.number(kSphere, f), 0.5f);
    EXPECT_EQ(tokens.number(kSphere, f), 7);
    EXPECT_EQ(tokens.number(kSphere, f), 100);
    EXPECT_EQ(tokens.number(kSphere, f), std::numeric_limits<float>::max());
    EXPECT_EQ(tokens.number(kSphere, f), 0);  // underflow rounds to zero, as strtof does
}

// The tokenizer reads plain decimals without std::from_chars (Clinger's fast path); it must
// give the same float, bit for bit, at the edges of that path too.
TEST(NffTokenizer, PlainDecimalsReadAsFromCharsReadsThem) {
    std::mt19937 random(7);
    std::vector<std::string> texts = {"16777216",  "16777217",     "-16777215",   "0.16777216",
                                      "1.6777217", "0.0000000001", "1234567.891", "9.999999",
                                      "0.1",       "-0.3",         "100000",      "00000000012.5",
                                      "2.",        "-.75"};
    for (int i = 0; i < 20000; ++i) {
        std::string text = std::uniform_int_distribution<int>(0, 1)(random) ? "-" : "";
        const int digits = std::uniform_int_distribution<int>(1, 10)(random);
        const int point = std::uniform_int_distribution<int>(0, digits)(random);
        for (int d = 0; d < digits; ++d) {
            if (d == point) text += '.';
            text += char('0' + std::uniform_int_distribution<int>(0, 9)(random));
        }
        texts.push_back(text);
    }
    for (const std::string& text : texts) {
        NffTokenizer tokens(text, "t.nff");
        float expected = 0;
        const char* first = text.data() + (text[0] == '+' ? 1 : 0);
        std::from_chars(first, text.data() + text.size(), expected);
        const float read = tokens.number(kSphere, {"radius"});
        EXPECT_EQ(std::bit_cast<std::uint32_t>(read), std::bit_cast<std::uint32_t>(expected))
            << text;
    }
}

std::string number_error(std::string_view text) {
    NffTokenizer tokens(text, "t.nff");
    try {
        tokens.number(kSphere, {"radius", 2});
    } catch (const SceneError& e) {
        return e.message();
    }
    return "(no error)";
}

TEST(NffTokenizer, BadNumbersSayWhatWasExpected) {
    EXPECT_EQ(number_error("abc"),
              "expected a number for the sphere's vertex 2 radius, got \"abc\"");
    EXPECT_EQ(number_error("1.5x"),
              "expected a number for the sphere's vertex 2 radius, got \"1.5x\"");
    EXPECT_EQ(number_error("+-1"),
              "expected a number for the sphere's vertex 2 radius, got \"+-1\"");
    EXPECT_EQ(number_error("0x10"),
              "expected a number for the sphere's vertex 2 radius, got \"0x10\"");
    EXPECT_EQ(number_error("nan"),
              "the sphere's vertex 2 radius must be a finite number, got \"nan\"");
    EXPECT_EQ(number_error("-inf"),
              "the sphere's vertex 2 radius must be a finite number, got \"-inf\"");
    EXPECT_EQ(number_error("3.5e38"),
              "the sphere's vertex 2 radius is out of the range of a float: \"3.5e38\"");
    EXPECT_EQ(number_error("1e400"),
              "the sphere's vertex 2 radius is out of the range of a float: \"1e400\"");
}

TEST(NffTokenizer, IntegersSaturateSoThatBoundsRejectThem) {
    NffTokenizer tokens("12 -3 99999999999999999999 -99999999999999999999 +7", "t.nff");
    const NffField f{"vertex count"};
    for (const std::int64_t expected :
         {std::int64_t(12), std::int64_t(-3), std::numeric_limits<std::int64_t>::max(),
          std::numeric_limits<std::int64_t>::min(), std::int64_t(7)}) {
        EXPECT_EQ(tokens.integer_of(tokens.next(), kSphere, f), expected);
    }
    NffTokenizer fraction("3.0", "t.nff");
    EXPECT_THROW(fraction.integer_of(fraction.next(), kSphere, f), SceneError);
}

TEST(NffTokenizer, EndOfFileErrorsPointJustPastTheLastToken) {
    NffTokenizer tokens("s 1 2\n\n# trailing comment\n", "t.nff");
    const NffEntity sphere{"sphere", tokens.next()};
    tokens.number(sphere, {"center x"});
    tokens.number(sphere, {"center y"});
    try {
        tokens.number(sphere, {"center z"});
        ADD_FAILURE() << "no error";
    } catch (const SceneError& e) {
        EXPECT_EQ(e.message(),
                  "the file ends inside the sphere that starts at line 1: expected the sphere's "
                  "center z");
        EXPECT_EQ(e.location().line, 1);
        EXPECT_EQ(e.location().column, 6);
        EXPECT_EQ(e.source_line(), "s 1 2");
    }
    // Nothing read at all: no line to point at.
    const NffTokenizer empty("", "t.nff");
    EXPECT_EQ(empty.error_at_end("x").location().line, 0);
}

TEST(NffTokenizer, ErrorsQuoteTheLineWithoutItsCarriageReturn) {
    NffTokenizer tokens("a\r\nbb cc\r\n", "t.nff");
    tokens.next();
    tokens.next();
    const SceneError e = tokens.error_at(tokens.next(), "bad");
    EXPECT_EQ(e.location().line, 2);
    EXPECT_EQ(e.location().column, 4);
    EXPECT_EQ(e.source_line(), "bb cc");
    EXPECT_EQ(e.span(), 2);
}

TEST(NffTokenizer, QuotedTokensAreCutShort) {
    EXPECT_EQ(quote("abc"), "\"abc\"");
    EXPECT_EQ(quote(std::string(50, 'y')), "\"" + std::string(40, 'y') + "...\"");
}

}  // namespace
}  // namespace glint
