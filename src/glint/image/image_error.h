// The one exception of the image module: a file could not be read or written. Its message
// starts with the file's path, so the user always knows which file is at fault.
#pragma once

#include <filesystem>
#include <stdexcept>
#include <string>

namespace glint {

struct ImageError : std::runtime_error {
    std::filesystem::path file;  // empty when no file is involved (e.g. comparing two images)
    std::string detail;          // the message without the file name

    explicit ImageError(const std::string& message)
        : std::runtime_error(message), detail(message) {}
    ImageError(const std::filesystem::path& file_, const std::string& detail_)
        : std::runtime_error(file_.string() + ": " + detail_), file(file_), detail(detail_) {}
};

}  // namespace glint
