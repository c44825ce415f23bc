// The error examples of docs/scene-format.md are what glint prints: each `yaml` block of its
// Errors section (whose first line, a comment, names the file) is loaded, and the error, formatted
// as the command line prints it, must equal the `text` block that follows.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "glint/scene/scene_error.h"
#include "glint/scene/yaml/yaml_scene_loader.h"

namespace glint {
namespace {

struct Example {
    std::string file, scene, printed;
};

std::string read_doc() {
    std::ifstream in(std::filesystem::path(GLINT_SOURCE_DIR) / "docs/scene-format.md");
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

// The body of the next fenced block of the language at or after `at`; `at` moves past it.
std::string next_block(const std::string& text, const std::string& language, std::size_t& at) {
    const std::string fence = "```" + language + "\n";
    const std::size_t start = text.find(fence, at);
    if (start == std::string::npos) return {};
    const std::size_t body = start + fence.size();
    const std::size_t end = text.find("```", body);
    at = end + 3;
    return text.substr(body, end - body);
}

std::vector<Example> examples() {
    const std::string doc = read_doc();
    const std::size_t section = doc.find("\n## Errors\n");
    const std::size_t section_end = doc.find("\n## ", section + 1);
    const std::string errors = doc.substr(section, section_end - section);
    std::vector<Example> out;
    std::size_t at = 0;
    for (;;) {
        const std::string scene = next_block(errors, "yaml", at);
        if (scene.empty()) break;
        Example e;
        e.scene = scene;
        e.file = scene.substr(2, scene.find('\n') - 2);  // "# scenes/cornell.yaml"
        e.printed = next_block(errors, "text", at);
        out.push_back(e);
    }
    return out;
}

TEST(SceneFormatDoc, ErrorExamplesAreWhatGlintPrints) {
    const std::vector<Example> all = examples();
    ASSERT_GE(all.size(), 2u);
    for (const Example& e : all) {
        SCOPED_TRACE(e.scene);
        try {
            parse_yaml_scene(e.scene, e.file);
            ADD_FAILURE() << "no error";
        } catch (const SceneError& error) {
            EXPECT_EQ(format_scene_error(error), e.printed);
        }
    }
}

}  // namespace
}  // namespace glint
