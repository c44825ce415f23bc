// Whole-file reads with transparent gunzip: plain and gzipped text, multi-member files, the size
// limit on plain and decompressed text (a gzip bomb), and damaged files.
#include "glint/scene/gzip_file.h"

#include <gtest/gtest.h>
#include <zlib.h>

#include <filesystem>
#include <fstream>
#include <string>

namespace glint {
namespace {

const std::filesystem::path kOut = std::filesystem::path(GLINT_TEST_OUTPUT_DIR) / "gzip_file";

std::string gzip(const std::string& text) {
    z_stream s{};
    // windowBits 15 + 16: a gzip wrapper, as `gzip -9` writes.
    EXPECT_EQ(deflateInit2(&s, 9, Z_DEFLATED, 15 + 16, 9, Z_DEFAULT_STRATEGY), Z_OK);
    std::string out(deflateBound(&s, uLong(text.size())), '\0');
    s.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(text.data()));
    s.avail_in = uInt(text.size());
    s.next_out = reinterpret_cast<Bytef*>(out.data());
    s.avail_out = uInt(out.size());
    EXPECT_EQ(deflate(&s, Z_FINISH), Z_STREAM_END);
    out.resize(s.total_out);
    deflateEnd(&s);
    return out;
}

std::filesystem::path write(const std::string& name, const std::string& bytes) {
    std::filesystem::create_directories(kOut);
    const auto path = kOut / name;
    std::ofstream(path, std::ios::binary) << bytes;
    return path;
}

std::string error_of(const std::filesystem::path& file, std::uint64_t max_bytes = 1 << 20) {
    try {
        read_maybe_gzipped(file, max_bytes);
    } catch (const SceneError& e) {
        EXPECT_EQ(e.location().file, file.string());
        EXPECT_EQ(e.location().line, 0);
        return e.message();
    }
    return "(no error)";
}

// Text that compresses well but not trivially: lines of an NFF file.
std::string sample_text(int lines) {
    std::string text;
    for (int i = 0; i < lines; ++i) text += "s " + std::to_string(i) + " 0.5 -1e-3 0.25\n";
    return text;
}

TEST(GzipFile, PlainFilesAreReadAsTheyAre) {
    const std::string text = sample_text(1000);
    EXPECT_EQ(read_maybe_gzipped(write("plain.nff", text), 1 << 20), text);
    EXPECT_EQ(read_maybe_gzipped(write("empty.nff", ""), 1 << 20), "");
}

TEST(GzipFile, GzippedFilesAreDecompressedWhateverTheirName) {
    const std::string text = sample_text(20000);  // several 64 KiB blocks
    const std::string packed = gzip(text);
    EXPECT_LT(packed.size(), text.size() / 4);
    EXPECT_EQ(read_maybe_gzipped(write("a.nff.gz", packed), 1 << 20), text);
    EXPECT_EQ(read_maybe_gzipped(write("a-without-suffix.nff", packed), 1 << 20), text);
}

TEST(GzipFile, AllMembersOfAMultiMemberFileAreJoined) {
    const std::string a = sample_text(10), b = "# the second member\n";
    EXPECT_EQ(read_maybe_gzipped(write("two.nff.gz", gzip(a) + gzip(b)), 1 << 20), a + b);
}

TEST(GzipFile, TheLimitHoldsForPlainAndDecompressedText) {
    const std::string text = sample_text(100);
    const auto plain = write("limit.nff", text);
    EXPECT_EQ(read_maybe_gzipped(plain, text.size()), text);  // exactly at the limit
    EXPECT_EQ(error_of(plain, text.size() - 1), "scene file is larger than the limit of " +
                                                    std::to_string(text.size() - 1) + " bytes");
    const auto packed = write("limit.nff.gz", gzip(text));
    EXPECT_EQ(read_maybe_gzipped(packed, text.size()), text);
    EXPECT_EQ(error_of(packed, text.size() - 1),
              "scene file decompresses to more than the limit of " +
                  std::to_string(text.size() - 1) + " bytes");
}

TEST(GzipFile, AGzipBombStopsAtTheLimit) {
    // 16 MiB of zeros pack into about 16 KiB; only the first MiB is ever held.
    const std::string bomb = gzip(std::string(std::size_t(16) << 20, '\0'));
    EXPECT_LT(bomb.size(), std::size_t(32) << 10);
    EXPECT_EQ(error_of(write("bomb.nff.gz", bomb), 1 << 20),
              "scene file decompresses to more than the limit of 1 MiB");
}

TEST(GzipFile, DamagedGzipDataIsAnError) {
    const std::string packed = gzip(sample_text(2000));
    EXPECT_EQ(error_of(write("truncated.nff.gz", packed.substr(0, packed.size() / 2))),
              "cannot read scene file: the gzip data is truncated");
    EXPECT_EQ(error_of(write("no-trailer.nff.gz", packed.substr(0, packed.size() - 3))),
              "cannot read scene file: the gzip data is truncated");
    std::string corrupt = packed;
    for (std::size_t i = 20; i < 60; ++i) corrupt[i] = char(corrupt[i] ^ 0x5a);
    EXPECT_TRUE(error_of(write("corrupt.nff.gz", corrupt))
                    .starts_with("cannot read scene file: corrupt gzip data ("));
    EXPECT_TRUE(error_of(write("trailing.nff.gz", packed + "garbage after the stream"))
                    .starts_with("cannot read scene file: corrupt gzip data ("));
    EXPECT_EQ(error_of(write("not-gzip.nff.gz", "s 0 0 0 1\n")),
              "cannot read scene file: it is named .gz but is not gzip-compressed");
}

TEST(GzipFile, MissingFilesAndDirectoriesAreErrors) {
    EXPECT_TRUE(error_of(kOut / "no-such-file.nff").starts_with("cannot read scene file: "));
    std::filesystem::create_directories(kOut / "a-directory.nff");
    EXPECT_EQ(error_of(kOut / "a-directory.nff"), "cannot read scene file: it is a directory");
}

}  // namespace
}  // namespace glint
