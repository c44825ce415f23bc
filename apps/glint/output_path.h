// The files `glint render` writes: checked before anything is loaded, so a bad -o fails at once
// rather than after a long render, and the sibling that takes an interrupted render's tiles.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

namespace glint::cli {

// Why `file` cannot be written, or nothing: it must not be a directory, and its directory must
// exist and be writable. The reason reads `cannot write "x/y.png": directory "x" does not
// exist`. A file that exists is fine: it is replaced by renaming, which needs only the
// directory's permission.
std::optional<std::string> unwritable_reason(const std::filesystem::path& file);

// As unwritable_reason, and the extension must name an image format.
std::optional<std::string> unwritable_image_reason(const std::filesystem::path& image);

// "<stem>.partial<ext>" beside `output`: showcase.png -> showcase.partial.png. The format's
// extension stays last, so the partial image is written and read like the full one.
std::filesystem::path partial_output_path(const std::filesystem::path& output);

// Where a part of a render of `output` goes: "out.exr.part3of8". The parts' files of one output
// differ by name, so that machines sharing a folder write beside each other.
std::filesystem::path part_file_path(const std::filesystem::path& output, int index, int count);
// The output a part's file is of: "out.exr.part3of8" -> "out.exr"; none for another name.
std::optional<std::filesystem::path> output_of_part_file(const std::filesystem::path& part_file);

}  // namespace glint::cli
