// stdio wrappers that report errno's reason with the file name.
#include "glint/image/file_io.h"

#include <cerrno>
#include <cstring>
#include <string>

#include "glint/image/image_error.h"

namespace glint {
namespace {

std::string system_reason() { return errno != 0 ? std::strerror(errno) : "unknown error"; }

}  // namespace

UniqueFile open_file(const std::filesystem::path& path, const char* mode) {
    errno = 0;
    UniqueFile file(std::fopen(path.c_str(), mode));
    if (!file) {
        const bool reading = mode[0] == 'r';
        throw ImageError(path, std::string("cannot open for ") + (reading ? "reading" : "writing") +
                                   ": " + system_reason());
    }
    return file;
}

void write_bytes(std::FILE* file, const void* data, std::size_t size,
                 const std::filesystem::path& path) {
    errno = 0;
    if (size != 0 && std::fwrite(data, 1, size, file) != size) {
        throw ImageError(path, "write failed: " + system_reason());
    }
}

void close_written_file(UniqueFile file, const std::filesystem::path& path) {
    errno = 0;
    const bool failed = std::ferror(file.get()) != 0;
    if (std::fclose(file.release()) != 0 || failed) {
        throw ImageError(path, "write failed: " + system_reason());
    }
}

std::vector<unsigned char> read_whole_file(const std::filesystem::path& path) {
    UniqueFile file = open_file(path, "rb");
    std::vector<unsigned char> bytes;
    unsigned char buffer[1 << 16];
    std::size_t n;
    while ((n = std::fread(buffer, 1, sizeof buffer, file.get())) > 0) {
        bytes.insert(bytes.end(), buffer, buffer + n);
    }
    if (std::ferror(file.get())) throw ImageError(path, "read failed: " + system_reason());
    return bytes;
}

}  // namespace glint
