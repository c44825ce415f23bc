// A string as a JSON string literal: quoted, with quotes, backslashes and control characters
// escaped. Enough for the few JSON objects glint writes by hand.
#pragma once

#include <cstdio>
#include <string>
#include <string_view>

namespace glint {

inline std::string json_string(std::string_view s) {
    std::string out = "\"";
    for (const char c : s) {
        if (c == '"' || c == '\\') {
            out += '\\';
            out += c;
        } else if (static_cast<unsigned char>(c) < 0x20) {
            char escape[8];
            std::snprintf(escape, sizeof escape, "\\u%04x", c);
            out += escape;
        } else {
            out += c;
        }
    }
    return out + "\"";
}

}  // namespace glint
