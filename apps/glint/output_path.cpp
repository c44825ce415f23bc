// Checks and names of the output files. The checks are a courtesy, not a guarantee: the file
// system can change during the render, and the writers still report what fails then.
#include "output_path.h"

#include <unistd.h>

#include <system_error>

#include "glint/image/image_format.h"

namespace glint::cli {

namespace {

std::string quoted(const std::filesystem::path& path) { return "\"" + path.string() + "\""; }

}  // namespace

std::optional<std::string> unwritable_reason(const std::filesystem::path& file) {
    const std::string prefix = "cannot write " + quoted(file) + ": ";
    std::error_code error;
    if (std::filesystem::is_directory(file, error)) return prefix + "it is a directory";
    const std::filesystem::path parent = file.has_parent_path() ? file.parent_path() : ".";
    const std::filesystem::file_status status = std::filesystem::status(parent, error);
    if (error && error != std::errc::no_such_file_or_directory)
        return prefix + "cannot reach directory " + quoted(parent) + ": " + error.message();
    if (!std::filesystem::exists(status))
        return prefix + "directory " + quoted(parent) + " does not exist";
    if (!std::filesystem::is_directory(status))
        return prefix + quoted(parent) + " is not a directory";
    // Creating the temporary and renaming it over the file need write and search permission.
    if (::access(parent.c_str(), W_OK | X_OK) != 0)
        return prefix + "directory " + quoted(parent) + " is not writable";
    return std::nullopt;
}

std::optional<std::string> unwritable_image_reason(const std::filesystem::path& image) {
    std::error_code error;
    // A directory first: `-o renders` means a folder, and "no extension" would mislead.
    if (!std::filesystem::is_directory(image, error) && !format_from_extension(image)) {
        const std::string formats = "; image formats are: " + std::string(known_image_extensions());
        const std::string extension = image.extension().string();
        if (extension.empty())
            return "cannot write " + quoted(image) +
                   ": the name has no extension to choose the image format" + formats;
        return "cannot write " + quoted(image) + ": unknown image format \"" + extension + "\"" +
               formats;
    }
    return unwritable_reason(image);
}

std::filesystem::path partial_output_path(const std::filesystem::path& output) {
    std::string name = output.stem().string();
    name += ".partial";
    name += output.extension().string();
    return std::filesystem::path(output).replace_filename(name);
}

std::filesystem::path part_file_path(const std::filesystem::path& output, int index, int count) {
    std::filesystem::path path = output;
    path += ".part" + std::to_string(index) + "of" + std::to_string(count);
    return path;
}

std::optional<std::filesystem::path> output_of_part_file(const std::filesystem::path& part_file) {
    const std::string name = part_file.filename().string();
    const std::size_t at = name.rfind(".part");
    if (at == std::string::npos || at == 0) return std::nullopt;
    const std::string suffix = name.substr(at + 5);  // "3of8"
    const std::size_t of = suffix.find("of");
    const auto digits = [](const std::string& s) {
        return !s.empty() && s.find_first_not_of("0123456789") == std::string::npos;
    };
    if (of == std::string::npos || !digits(suffix.substr(0, of)) || !digits(suffix.substr(of + 2)))
        return std::nullopt;
    return std::filesystem::path(part_file).replace_filename(name.substr(0, at));
}

}  // namespace glint::cli
