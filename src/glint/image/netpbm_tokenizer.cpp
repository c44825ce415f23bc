// The header tokenizer shared by the PPM and PFM readers.
#include "glint/image/netpbm_tokenizer.h"

namespace glint {
namespace {

bool is_space(unsigned char c) {
    return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' || c == '\f';
}

}  // namespace

std::string_view NetpbmTokenizer::next_token() {
    const std::size_t n = bytes_.size();
    while (position_ < n) {
        if (is_space(bytes_[position_])) {
            ++position_;
        } else if (allow_comments_ && bytes_[position_] == '#') {
            while (position_ < n && bytes_[position_] != '\n' && bytes_[position_] != '\r') {
                ++position_;
            }
        } else {
            break;
        }
    }
    const std::size_t start = position_;
    while (position_ < n && !is_space(bytes_[position_]) &&
           !(allow_comments_ && bytes_[position_] == '#')) {
        ++position_;
    }
    return {reinterpret_cast<const char*>(bytes_.data()) + start, position_ - start};
}

std::int64_t NetpbmTokenizer::next_positive(const std::string& field, std::int64_t max) {
    const std::string_view token = next_token();
    if (token.empty()) throw malformed("header ends before the " + field);
    const auto value = parse_decimal(token, max);
    if (!value || *value == 0) {
        throw malformed(field + " must be an integer from 1 to " + std::to_string(max) + ", got " +
                        quote_header_token(token));
    }
    return *value;
}

ImageError NetpbmTokenizer::malformed(const std::string& what) const {
    return ImageError(path_, "malformed " + format_ + ": " + what);
}

std::optional<std::size_t> NetpbmTokenizer::raster_start() const {
    if (position_ >= bytes_.size() || !is_space(bytes_[position_])) return std::nullopt;
    return position_ + 1;
}

std::optional<std::int64_t> parse_decimal(std::string_view token, std::int64_t max) {
    if (token.empty()) return std::nullopt;
    std::int64_t value = 0;
    for (const char c : token) {
        if (c < '0' || c > '9') return std::nullopt;
        value = value * 10 + (c - '0');
        if (value > max) return std::nullopt;
    }
    return value;
}

std::string quote_header_token(std::string_view token) {
    constexpr std::size_t kMaxShown = 16;
    std::string shown(token.substr(0, kMaxShown));
    for (char& c : shown) {
        if (static_cast<unsigned char>(c) < 0x20 || static_cast<unsigned char>(c) >= 0x7f) c = '?';
    }
    return "\"" + shown + (token.size() > kMaxShown ? "...\"" : "\"");
}

}  // namespace glint
