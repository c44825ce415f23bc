// Quoting a name or token from a scene file for a message: in double quotes, control characters
// escaped, long text cut short with "...".
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace glint {

// Names and tokens longer than this are cut short.
inline constexpr std::size_t kMaxQuoted = 40;

// Text longer than max_length is cut short.
std::string quote(std::string_view text, std::size_t max_length = kMaxQuoted);

}  // namespace glint
