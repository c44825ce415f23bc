// Where an interrupted render's image goes.
#include "output_path.h"

#include <string>

namespace glint::cli {

std::filesystem::path partial_output_path(const std::filesystem::path& output) {
    std::string name = output.stem().string();
    name += ".partial";
    name += output.extension().string();
    return std::filesystem::path(output).replace_filename(name);
}

}  // namespace glint::cli
