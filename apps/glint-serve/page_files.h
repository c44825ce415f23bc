// The page's files, compiled into glint-serve from apps/glint-serve/page (embed_page.cmake).
#pragma once

#include <optional>
#include <string_view>

namespace glint::serve {

struct PageFile {
    std::string_view name;     // "index.html", "app.js"
    std::string_view type;     // its media type, for Content-Type
    std::string_view content;  // its bytes
};

// The file of that name, none for any other name.
std::optional<PageFile> page_file(std::string_view name);

}  // namespace glint::serve
