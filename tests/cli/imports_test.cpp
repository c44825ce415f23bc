// glint runs no programs and opens no network connection: neither the executable nor a library
// it loads imports a function that would (docs/reliability.md, "Sandbox"). libc, which defines
// them, is not checked; a library that does not import them cannot call them by name.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace glint {
namespace {

namespace fs = std::filesystem;

// Starting programs, and opening or resolving network connections.
const std::set<std::string> kForbidden = {
    "system",  "popen",   "posix_spawn", "posix_spawnp",  "fork",           "vfork",
    "execl",   "execle",  "execlp",      "execv",         "execve",         "execvp",
    "execvpe", "fexecve", "socket",      "connect",       "bind",           "listen",
    "accept",  "accept4", "getaddrinfo", "gethostbyname", "gethostbyname_r"};

// The standard output of a shell command (the test's, not glint's).
std::string output_of(const std::string& command) {
    const fs::path out = fs::path(GLINT_TEST_OUTPUT_DIR) / "imports_test.txt";
    fs::create_directories(out.parent_path());
    if (std::system((command + " > '" + out.string() + "' 2>/dev/null").c_str()) != 0) return {};
    std::ifstream in(out);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

// The shared libraries the executable loads, as ldd finds them ("name => /path (0x...)"),
// without libc and the dynamic loader, which provide these functions, and without the
// sanitizers' runtimes (test builds only), which start a symbolizer by design.
std::vector<std::string> libraries_of(const std::string& executable) {
    std::vector<std::string> libraries;
    std::istringstream lines(output_of("ldd '" + executable + "'"));
    std::string line;
    while (std::getline(lines, line)) {
        const auto arrow = line.find("=> /");
        if (arrow == std::string::npos) continue;
        const std::string path = line.substr(arrow + 3, line.find(" (", arrow) - arrow - 3);
        const std::string name = fs::path(path).filename().string();
        if (name.starts_with("libc.so") || name.starts_with("ld-linux") ||
            name.starts_with("libasan") || name.starts_with("libubsan") ||
            name.starts_with("libtsan") || name.starts_with("liblsan"))
            continue;
        libraries.push_back(path);
    }
    return libraries;
}

TEST(Imports, NeitherGlintNorItsLibrariesCanStartProgramsOrOpenTheNetwork) {
    if (output_of("command -v nm && command -v ldd").empty())
        GTEST_SKIP() << "nm (binutils) or ldd is not installed";
    std::vector<std::string> files = libraries_of(GLINT_BINARY);
    ASSERT_GE(files.size(), 3u) << "ldd found too few libraries: is " GLINT_BINARY " dynamic?";
    files.insert(files.begin(), GLINT_BINARY);
    for (const std::string& file : files) {
        std::istringstream symbols(output_of("nm -D --undefined-only '" + file + "'"));
        std::string line;
        int count = 0;
        while (std::getline(symbols, line)) {
            ++count;
            std::string name = line.substr(line.find_last_of(' ') + 1);
            name = name.substr(0, name.find('@'));  // without its version, "socket@GLIBC_2.2.5"
            EXPECT_EQ(kForbidden.count(name), 0u) << file << " imports " << name;
        }
        EXPECT_GT(count, 0) << "nm listed no imports of " << file;
    }
}

}  // namespace
}  // namespace glint
