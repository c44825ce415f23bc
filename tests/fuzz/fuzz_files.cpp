// The fuzz targets' temporary folder: named after the process so that parallel jobs (-jobs=N)
// never share files, and removed by a static destructor when libFuzzer exits.
#include "fuzz_files.h"

#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <string>
#include <system_error>

namespace glint::fuzz {

namespace {

struct Folder {
    std::filesystem::path path;

    Folder()
        : path(std::filesystem::temp_directory_path() /
               ("glint-fuzz-" + std::to_string(::getpid()))) {
        std::filesystem::create_directories(path);
    }
    ~Folder() {
        std::error_code ignored;
        std::filesystem::remove_all(path, ignored);
    }
};

}  // namespace

const std::filesystem::path& fuzz_folder() {
    static const Folder folder;
    return folder.path;
}

std::filesystem::path write_fuzz_file(std::string_view name, std::span<const std::uint8_t> bytes) {
    const std::filesystem::path path = fuzz_folder() / name;
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
    out.close();
    if (!out) std::abort();  // a harness that cannot write its file would fuzz nothing
    return path;
}

std::filesystem::path write_fuzz_file(std::string_view name, std::string_view text) {
    return write_fuzz_file(
        name, std::span(reinterpret_cast<const std::uint8_t*>(text.data()), text.size()));
}

SplitInput split_at_nul(std::span<const std::uint8_t> bytes) {
    const auto nul = std::find(bytes.begin(), bytes.end(), std::uint8_t(0));
    if (nul == bytes.end()) return {bytes, {}};
    const auto at = std::size_t(nul - bytes.begin());
    return {bytes.first(at), bytes.subspan(at + 1)};
}

}  // namespace glint::fuzz
