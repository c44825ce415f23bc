#include "glint/image/file_io.h"

#include <gtest/gtest.h>

#include "test_files.h"

namespace glint {
namespace {

TEST(ImageFileIo, MissingFileSaysWhy) {
    const auto path = testing::fresh_test_dir() / "missing.ppm";
    testing::expect_image_error([&] { read_whole_file(path); }, path,
                                "cannot open for reading: No such file or directory");
    testing::expect_image_error([&] { open_file(path / "x.png", "wb"); }, path / "x.png",
                                "cannot open for writing:");
}

TEST(ImageFileIo, ReadingAFolderIsAnError) {
    const auto dir = testing::fresh_test_dir();
    testing::expect_image_error([&] { read_whole_file(dir); }, dir, "Is a directory");
}

TEST(ImageFileIo, WritesAndReadsBackBytes) {
    const auto path = testing::fresh_test_dir() / "bytes.bin";
    UniqueFile file = open_file(path, "wb");
    write_bytes(file.get(), "ab\0c", 4, path);
    close_written_file(std::move(file), path);
    EXPECT_EQ(read_whole_file(path), (std::vector<unsigned char>{'a', 'b', 0, 'c'}));
}

}  // namespace
}  // namespace glint
