// Small stdio helpers for the format readers and writers: every failure becomes an ImageError
// that names the file and says what the system reported.
#pragma once

#include <cstddef>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <vector>

namespace glint {

struct FileCloser {
    void operator()(std::FILE* file) const { std::fclose(file); }
};
using UniqueFile = std::unique_ptr<std::FILE, FileCloser>;

// fopen with "rb" or "wb"; throws ImageError ("cannot open for reading: <reason>").
UniqueFile open_file(const std::filesystem::path& path, const char* mode);

// Writes all bytes or throws ImageError.
void write_bytes(std::FILE* file, const void* data, std::size_t size,
                 const std::filesystem::path& path);

// Closes a file that was written, throwing ImageError if buffered data could not be flushed
// (a full disk often shows up only here).
void close_written_file(UniqueFile file, const std::filesystem::path& path);

// The whole file's bytes; for the small text-headed formats (PPM, PFM) that are parsed in
// memory, which makes truncation a bounds check instead of a read error.
std::vector<unsigned char> read_whole_file(const std::filesystem::path& path);

}  // namespace glint
