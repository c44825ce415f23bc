// Compiler-style rendering of a SceneError: the location, the message, the source line with a
// caret under the offending token, and the notes.
#include "glint/scene/scene_error.h"

#include <algorithm>
#include <cstdio>

namespace glint {

std::string format_scene_error(const SceneError& error) {
    const SourceLocation& at = error.location();
    std::string out = at.file;
    if (at.line > 0) {
        out += ':' + std::to_string(at.line);
        if (at.column > 0) out += ':' + std::to_string(at.column);
    }
    out += ": error: " + error.message() + '\n';

    if (at.line > 0 && !error.source_line().empty()) {
        // The gutter is at least four digits wide, as GCC's is, so that excerpts of nearby lines
        // in successive errors line up.
        char number[16];
        std::snprintf(number, sizeof number, " %4d", at.line);
        const std::string gutter(number);
        out += gutter + " | " + error.source_line() + '\n';
        if (at.column > 0) {
            // Tabs before the column are kept so that the caret lines up however the terminal
            // expands them.
            const std::string& line = error.source_line();
            std::string pad;
            for (int i = 0; i < at.column - 1; ++i) {
                pad += (std::size_t(i) < line.size() && line[std::size_t(i)] == '\t') ? '\t' : ' ';
            }
            // The caret never runs past the end of the line, however wide the span claims to be.
            const int room = std::max(1, int(line.size()) - (at.column - 1));
            const int span = std::clamp(error.span(), 1, room);
            out += std::string(gutter.size(), ' ') + " | " + pad + '^' +
                   std::string(std::size_t(span - 1), '~') + '\n';
        }
    }
    for (const std::string& note : error.notes()) out += "note: " + note + '\n';
    return out;
}

}  // namespace glint
