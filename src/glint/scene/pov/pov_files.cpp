#include "glint/scene/pov/pov_files.h"

#include <algorithm>

namespace glint {

std::uint32_t PovFiles::add(std::string name, std::string text, const PovPosition* included_at) {
    File file{std::move(name), std::move(text), included_at != nullptr, {}};
    if (included_at) file.included_at = *included_at;
    files_.push_back(std::move(file));
    return std::uint32_t(files_.size() - 1);
}

SceneError PovFiles::error_at(const PovPosition& where, std::string message,
                              std::vector<std::string> notes) const {
    const File& file = files_.at(where.file);
    // The text of the line, without its newline.
    std::string_view text = file.text;
    std::size_t start = 0;
    for (std::uint32_t line = 1; line < where.line && start < text.size(); ++line) {
        const std::size_t newline = text.find('\n', start);
        if (newline == std::string_view::npos) {
            start = text.size();
            break;
        }
        start = newline + 1;
    }
    std::size_t end = std::min(text.find('\n', start), text.size());
    if (end > start && text[end - 1] == '\r') --end;
    for (const File* f = &file; f->included;) {
        const File& outer = files_.at(f->included_at.file);
        notes.push_back("included from " + outer.name + ":" + std::to_string(f->included_at.line) +
                        ":" + std::to_string(f->included_at.column));
        f = &outer;
    }
    return SceneError({file.name, int(where.line), int(where.column)}, std::move(message),
                      std::move(notes), std::string(text.substr(start, end - start)),
                      int(std::max<std::uint32_t>(where.length, 1)));
}

}  // namespace glint
