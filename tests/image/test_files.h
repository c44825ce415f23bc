// Helpers for the image tests: a fresh output folder per test, raw file contents, and a check
// that an action fails with an ImageError naming the right file.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <string_view>
#include <vector>

#include "glint/image/image_error.h"

namespace glint::testing {

// GLINT_TEST_OUTPUT_DIR/<Suite>.<Test>, emptied: tests may run in parallel processes, and the
// atomic-write tests list the folder to prove no temporary is left behind.
inline std::filesystem::path fresh_test_dir() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    const std::filesystem::path dir = std::filesystem::path(GLINT_TEST_OUTPUT_DIR) /
                                      (std::string(info->test_suite_name()) + "." + info->name());
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

inline std::string read_file(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

inline void write_file(const std::filesystem::path& path, std::string_view contents) {
    std::ofstream out(path, std::ios::binary);
    out.write(contents.data(), std::streamsize(contents.size()));
}

inline std::vector<std::string> file_names_in(const std::filesystem::path& dir) {
    std::vector<std::string> names;
    for (const auto& entry : std::filesystem::directory_iterator(dir)) {
        names.push_back(entry.path().filename().string());
    }
    return names;
}

// Expects `action` to throw an ImageError whose message is "<file>: ..." and contains `fragment`.
template <typename Action>
void expect_image_error(Action&& action, const std::filesystem::path& file,
                        std::string_view fragment) {
    try {
        action();
        ADD_FAILURE() << "expected an ImageError about " << file;
    } catch (const ImageError& e) {
        const std::string message = e.what();
        EXPECT_EQ(e.file, file) << message;
        EXPECT_EQ(message.rfind(file.string() + ": ", 0), 0u) << message;
        EXPECT_NE(message.find(fragment), std::string::npos)
            << "message: " << message << "\nexpected to contain: " << fragment;
    }
}

}  // namespace glint::testing
