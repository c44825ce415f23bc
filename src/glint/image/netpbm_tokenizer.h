// Tokenising the text parts of PPM and PFM files held in memory: whitespace-separated tokens,
// with '#' comments running to the end of the line where the format allows them (PPM).
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>

#include "glint/image/image_error.h"

namespace glint {

class NetpbmTokenizer {
public:
    // `path` and `format` ("PPM", "PFM") only name the file in error messages.
    NetpbmTokenizer(std::span<const unsigned char> bytes, const std::filesystem::path& path,
                    std::string format, bool allow_comments)
        : bytes_(bytes), path_(path), format_(std::move(format)), allow_comments_(allow_comments) {}

    // The next token, or an empty view at the end of the data.
    std::string_view next_token();

    // The next token as an integer from 1 to max; throws malformed() naming the field otherwise.
    std::int64_t next_positive(const std::string& field, std::int64_t max);

    // "<file>: malformed <format>: <what>", for the reader to throw.
    ImageError malformed(const std::string& what) const;

    // Where the raster starts: the single whitespace byte after the last token must be there
    // and is skipped. Nothing if the data ends or that byte is not whitespace.
    std::optional<std::size_t> raster_start() const;

private:
    std::span<const unsigned char> bytes_;
    std::filesystem::path path_;
    std::string format_;
    bool allow_comments_;
    std::size_t position_ = 0;
};

// A token of decimal digits as a number no larger than `max`; nothing for anything else
// (signs, letters, empty, too large).
std::optional<std::int64_t> parse_decimal(std::string_view token, std::int64_t max);

// A token quoted for an error message, shortened if long: "abc" or "xxxxxxxxxxxxxxxx...".
std::string quote_header_token(std::string_view token);

}  // namespace glint
