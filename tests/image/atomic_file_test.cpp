#include "glint/image/atomic_file.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <vector>

#include "glint/image/image_error.h"
#include "test_files.h"

namespace glint {
namespace {

using testing::fresh_test_dir;
using testing::read_file;
using testing::write_file;
using Names = std::vector<std::string>;

TEST(AtomicFile, ReplacesTheTargetWithWhatWasWritten) {
    const auto dir = fresh_test_dir();
    const auto target = dir / "out.png";
    write_file(target, "old");
    write_file_atomically(
        target, [](const std::filesystem::path& temporary) { write_file(temporary, "new"); });
    EXPECT_EQ(read_file(target), "new");
    EXPECT_EQ(testing::file_names_in(dir), Names{"out.png"});
}

TEST(AtomicFile, TemporaryIsAHiddenSiblingThatKeepsTheExtension) {
    const auto dir = fresh_test_dir();
    std::vector<std::filesystem::path> temporaries;
    for (int i = 0; i < 2; ++i) {
        write_file_atomically(dir / "out.exr", [&](const std::filesystem::path& temporary) {
            temporaries.push_back(temporary);
            write_file(temporary, "x");
        });
    }
    ASSERT_EQ(temporaries.size(), 2u);
    for (const auto& t : temporaries) {
        EXPECT_EQ(t.parent_path(), dir);
        EXPECT_EQ(t.filename().string().rfind(".out.tmp-", 0), 0u) << t;
        EXPECT_EQ(t.extension(), ".exr");
    }
    EXPECT_NE(temporaries[0], temporaries[1]);
}

TEST(AtomicFile, KeepsTheOldFileAndRemovesTheTemporaryWhenTheWriterThrows) {
    const auto dir = fresh_test_dir();
    const auto target = dir / "out.png";
    write_file(target, "old");
    try {
        write_file_atomically(target, [](const std::filesystem::path& temporary) {
            write_file(temporary, "half a fi");
            throw std::runtime_error("disk on fire");
        });
        FAIL() << "the writer's exception should propagate";
    } catch (const std::runtime_error& e) {
        EXPECT_STREQ(e.what(), "disk on fire");
    }
    EXPECT_EQ(read_file(target), "old");
    EXPECT_EQ(testing::file_names_in(dir), Names{"out.png"});
}

TEST(AtomicFile, AnErrorAboutTheTemporaryIsReportedAgainstTheTarget) {
    const auto dir = fresh_test_dir();
    const auto target = dir / "out.png";
    testing::expect_image_error(
        [&] {
            write_file_atomically(target, [](const std::filesystem::path& temporary) {
                write_file(temporary, "x");
                throw ImageError(temporary,
                                 "cannot write \"" + temporary.string() + "\": disk full");
            });
        },
        target, "cannot write \"" + target.string() + "\": disk full");
    EXPECT_TRUE(testing::file_names_in(dir).empty());
}

TEST(AtomicFile, FailedRenameThrowsImageErrorAndLeavesNoTemporary) {
    const auto dir = fresh_test_dir();
    const auto target = dir / "out.png";
    std::filesystem::create_directories(target / "occupied");  // a non-empty folder is in the way
    testing::expect_image_error(
        [&] {
            write_file_atomically(target, [](const std::filesystem::path& temporary) {
                write_file(temporary, "new");
            });
        },
        target, "cannot move the finished file into place");
    EXPECT_EQ(testing::file_names_in(dir), Names{"out.png"});
    EXPECT_TRUE(std::filesystem::is_directory(target));
}

TEST(AtomicFile, WriterThatCreatesNothingIsAnError) {
    const auto dir = fresh_test_dir();
    const auto target = dir / "out.png";
    testing::expect_image_error(
        [&] { write_file_atomically(target, [](const std::filesystem::path&) {}); }, target,
        "cannot open the written file again: No such file or directory");
    EXPECT_TRUE(testing::file_names_in(dir).empty());
}

}  // namespace
}  // namespace glint
