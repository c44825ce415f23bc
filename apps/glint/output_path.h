// The image file `glint render` writes, and the sibling that takes an interrupted render's
// tiles so that the image already at the target survives a Ctrl-C.
#pragma once

#include <filesystem>

namespace glint::cli {

// "<stem>.partial<ext>" beside `output`: showcase.png -> showcase.partial.png. The format's
// extension stays last, so the partial image is written and read like the full one.
std::filesystem::path partial_output_path(const std::filesystem::path& output);

}  // namespace glint::cli
