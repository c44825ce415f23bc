// Double-quoting text for messages, with control characters escaped and long names cut short.
#include "glint/scene/quote.h"

namespace glint {

std::string quote(std::string_view text, std::size_t max_length) {
    std::string out = "\"";
    for (std::size_t i = 0; i < text.size() && i < max_length; ++i) {
        const auto c = static_cast<unsigned char>(text[i]);
        if (c == '"' || c == '\\') {
            out += '\\';
            out += char(c);
        } else if (c < 0x20 || c == 0x7f) {
            const char* hex = "0123456789abcdef";
            out += "\\x";
            out += hex[c >> 4];
            out += hex[c & 15];
        } else {
            out += char(c);
        }
    }
    if (text.size() > max_length) out += "...";
    return out + "\"";
}

}  // namespace glint
