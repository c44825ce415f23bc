// Quoting a name or token from a scene file for a message: in double quotes, control characters
// escaped, long text cut short with "...".
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace glint {

// Text longer than this is cut short.
inline constexpr std::size_t kMaxQuoted = 40;

std::string quote(std::string_view text);

}  // namespace glint
