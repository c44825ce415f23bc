// The NFF tokenizer: one pass over the text, counting lines as it goes so that every token knows
// its line and column without a second look. Numbers are parsed with std::from_chars, which is
// exact, locale-free and fast enough for files of hundreds of megabytes.
#include "glint/scene/nff/nff_tokenizer.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstring>
#include <limits>
#include <optional>

namespace glint {

namespace {

// Longer lines are not quoted whole in errors: a minified file can be one line of megabytes.
constexpr std::size_t kMaxQuotedLine = 4096;

// Each byte's class, looked up once rather than compared with six spaces: the loops below see
// every byte of files of hundreds of megabytes.
enum ByteClass : unsigned char { kTokenByte, kSpace, kNewline, kCommentStart };

constexpr std::array<ByteClass, 256> kByteClass = [] {
    std::array<ByteClass, 256> classes{};
    for (const char c : {' ', '\t', '\r', '\f', '\v'})
        classes[static_cast<unsigned char>(c)] = kSpace;
    classes['\n'] = kNewline;
    classes['#'] = kCommentStart;
    return classes;
}();

ByteClass class_of(char c) { return kByteClass[static_cast<unsigned char>(c)]; }

// Clinger's fast path: a plain decimal ("-0.996094") whose digits, read as a whole number,
// are at most 2^24, with at most 10 of them after the point, is that whole number divided by a
// power of ten: both exact in a float, so the one division rounds correctly and gives the float
// std::from_chars gives. Anything else (exponents, long mantissas, errors) returns nullopt.
std::optional<float> plain_decimal(std::string_view text) {
    constexpr std::uint32_t kExactInFloat = std::uint32_t(1) << 24;
    constexpr float kPowersOfTen[] = {1e0f, 1e1f, 1e2f, 1e3f, 1e4f, 1e5f,
                                      1e6f, 1e7f, 1e8f, 1e9f, 1e10f};
    std::size_t i = 0;
    const bool negative = !text.empty() && text[0] == '-';
    if (!text.empty() && (text[0] == '-' || text[0] == '+')) i = 1;
    std::uint32_t digits = 0;
    int count = 0, after_point = -1;  // -1 until the point is seen
    for (; i < text.size(); ++i) {
        const char c = text[i];
        if (c >= '0' && c <= '9') {
            digits = digits * 10 + std::uint32_t(c - '0');
            if (digits > kExactInFloat) return std::nullopt;
            ++count;
            if (after_point >= 0) ++after_point;
        } else if (c == '.' && after_point < 0) {
            after_point = 0;
        } else {
            return std::nullopt;
        }
    }
    if (count == 0 || after_point > 10) return std::nullopt;
    const float value = float(digits) / kPowersOfTen[std::max(after_point, 0)];
    return negative ? -value : value;
}

// std::from_chars rejects the leading '+' that C's strtod accepts.
const char* skip_plus(const char* first, const char* last) {
    if (last - first >= 2 && first[0] == '+' && first[1] != '+' && first[1] != '-')
        return first + 1;
    return first;
}

}  // namespace

std::string describe(const NffEntity& entity, const NffField& field) {
    std::string out = "the " + std::string(entity.name) + "'s ";
    if (field.vertex > 0) out += "vertex " + std::to_string(field.vertex) + " ";
    return out + field.name;
}

NffTokenizer::NffTokenizer(std::string_view text, std::string file_name)
    : text_(text), file_name_(std::move(file_name)) {}

void NffTokenizer::skip_space() {
    while (pos_ < text_.size()) {
        const ByteClass c = class_of(text_[pos_]);
        if (c == kNewline) {
            ++pos_;
            ++line_;
            line_start_ = pos_;
        } else if (c == kSpace) {
            ++pos_;
        } else if (c == kCommentStart) {
            const void* newline = std::memchr(text_.data() + pos_, '\n', text_.size() - pos_);
            pos_ = newline ? std::size_t(static_cast<const char*>(newline) - text_.data())
                           : text_.size();
        } else {
            return;
        }
    }
}

NffToken NffTokenizer::next() {
    skip_space();
    const std::size_t begin = pos_;
    while (pos_ < text_.size() && class_of(text_[pos_]) == kTokenByte) ++pos_;
    NffToken token{text_.substr(begin, pos_ - begin), line_,
                   std::uint32_t(begin - line_start_ + 1)};
    if (!token.at_end()) last_ = token;
    return token;
}

NffToken NffTokenizer::peek() {
    skip_space();  // consumes only what next() would skip anyway
    std::size_t end = pos_;
    while (end < text_.size() && class_of(text_[end]) == kTokenByte) ++end;
    return {text_.substr(pos_, end - pos_), line_, std::uint32_t(pos_ - line_start_ + 1)};
}

NffToken NffTokenizer::require(const NffEntity& entity, const NffField& field) {
    const NffToken token = next();
    if (token.at_end()) {
        throw error_at_end("the file ends inside the " + std::string(entity.name) +
                           " that starts at line " + std::to_string(entity.keyword.line) +
                           ": expected " + describe(entity, field));
    }
    return token;
}

float NffTokenizer::number_of(const NffToken& token, const NffEntity& entity,
                              const NffField& field) const {
    if (const auto plain = plain_decimal(token.text)) return *plain;
    const char* last = token.text.data() + token.text.size();
    const char* first = skip_plus(token.text.data(), last);
    float value = 0;
    auto [end, ec] = std::from_chars(first, last, value);
    if (ec == std::errc::result_out_of_range) {
        // Too small for a float rounds towards zero, as strtof does; too large is an error.
        double wide = 0;
        const auto [wide_end, wide_ec] = std::from_chars(first, last, wide);
        if (wide_ec != std::errc() || wide_end != last || !(std::abs(wide) < 1)) {
            throw error_at(token, describe(entity, field) +
                                      " is out of the range of a float: " + quote(token.text));
        }
        value = float(wide);
        end = last, ec = std::errc();
    }
    if (ec != std::errc() || end != last) {
        throw error_at(token, "expected a number for " + describe(entity, field) + ", got " +
                                  quote(token.text));
    }
    if (!std::isfinite(value)) {
        throw error_at(
            token, describe(entity, field) + " must be a finite number, got " + quote(token.text));
    }
    return value;
}

std::int64_t NffTokenizer::integer_of(const NffToken& token, const NffEntity& entity,
                                      const NffField& field) const {
    const char* last = token.text.data() + token.text.size();
    const char* first = skip_plus(token.text.data(), last);
    std::int64_t value = 0;
    const auto [end, ec] = std::from_chars(first, last, value);
    if (ec == std::errc::result_out_of_range && end == last) {
        // Saturate: the caller's bounds then reject it with the usual message.
        return *first == '-' ? std::numeric_limits<std::int64_t>::min()
                             : std::numeric_limits<std::int64_t>::max();
    }
    if (ec != std::errc() || end != last) {
        throw error_at(token, "expected a whole number for " + describe(entity, field) + ", got " +
                                  quote(token.text));
    }
    return value;
}

SceneError NffTokenizer::error_at(const NffToken& token, std::string message,
                                  std::vector<std::string> notes) const {
    const std::size_t offset = std::size_t(token.text.data() - text_.data());
    const std::size_t line_start = offset - (token.column - 1);
    std::string quoted_line;
    if (token.column <= kMaxQuotedLine) {
        const std::size_t limit = std::min(text_.size(), line_start + kMaxQuotedLine);
        std::size_t end = line_start;
        while (end < limit && text_[end] != '\n') ++end;
        while (end > line_start && text_[end - 1] == '\r') --end;
        quoted_line = std::string(text_.substr(line_start, end - line_start));
    }
    return SceneError({file_name_, int(token.line), int(token.column)}, std::move(message),
                      std::move(notes), std::move(quoted_line),
                      int(std::max<std::size_t>(1, token.text.size())));
}

SceneError NffTokenizer::error_at_end(std::string message, std::vector<std::string> notes) const {
    if (last_.at_end()) return SceneError({file_name_, 0, 0}, std::move(message), std::move(notes));
    // An empty token just past the last one, on its line.
    const std::size_t end = std::size_t(last_.text.data() - text_.data()) + last_.text.size();
    const NffToken past{text_.substr(end, 0), last_.line,
                        std::uint32_t(last_.column + last_.text.size())};
    return error_at(past, std::move(message), std::move(notes));
}

}  // namespace glint
