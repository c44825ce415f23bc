// Files for the fuzz targets of loaders that read by path: one folder per process under the
// system's temporary folder, removed when the process exits.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <span>
#include <string_view>

namespace glint::fuzz {

// The process's folder, made on first use.
const std::filesystem::path& fuzz_folder();

// Writes `bytes` to `name` in the process's folder (replacing what was there) and returns its
// path.
std::filesystem::path write_fuzz_file(std::string_view name, std::span<const std::uint8_t> bytes);
std::filesystem::path write_fuzz_file(std::string_view name, std::string_view text);

// The bytes before the first NUL, and those after it (empty when there is none): how the text
// targets take a second file (an OBJ's MTL, a glTF's buffer) from one input.
struct SplitInput {
    std::span<const std::uint8_t> first;
    std::span<const std::uint8_t> second;
};
SplitInput split_at_nul(std::span<const std::uint8_t> bytes);

}  // namespace glint::fuzz
