// Locating errors in the YAML text: the line of a mark and the extent of a node's token.
#include "glint/scene/yaml/yaml_source.h"

#include <yaml-cpp/depthguard.h>

#include <algorithm>
#include <new>
#include <optional>

namespace glint {

namespace {

// The index of the character that closes the quote or bracket opening at `begin`, if it is on
// the same line.
std::optional<std::size_t> closing(std::string_view line, std::size_t begin) {
    const char open = line[begin];
    if (open == '"' || open == '\'') {
        for (std::size_t i = begin + 1; i < line.size(); ++i) {
            if (open == '"' && line[i] == '\\') {
                ++i;
            } else if (line[i] == open) {
                if (open == '\'' && i + 1 < line.size() && line[i + 1] == '\'') {
                    ++i;  // '' is an escaped quote inside single quotes
                } else {
                    return i;
                }
            }
        }
        return std::nullopt;
    }
    int depth = 0;
    for (std::size_t i = begin; i < line.size(); ++i) {
        const char c = line[i];
        if (c == '"' || c == '\'') {
            const auto end = closing(line, i);
            if (!end) return std::nullopt;
            i = *end;
        } else if (c == '[' || c == '{') {
            ++depth;
        } else if (c == ']' || c == '}') {
            if (--depth == 0) return i;
        }
    }
    return std::nullopt;
}

}  // namespace

YamlSource::YamlSource(std::string_view text, std::string file_name)
    : text_(text), file_name_(std::move(file_name)) {
    line_starts_.push_back(0);
    for (std::size_t i = 0; i < text_.size(); ++i) {
        if (text_[i] == '\n') line_starts_.push_back(i + 1);
    }
}

std::string_view YamlSource::line(int index) const {
    if (index < 0 || std::size_t(index) >= line_starts_.size()) return {};
    const std::size_t begin = line_starts_[std::size_t(index)];
    std::size_t end = text_.find('\n', begin);
    if (end == std::string_view::npos) end = text_.size();
    if (end > begin && text_[end - 1] == '\r') --end;
    return text_.substr(begin, end - begin);
}

std::string YamlSource::warning_at(const YAML::Node& node, const std::string& message) const {
    const TextPosition at = text_position(node.Mark());
    return file_name_ + ":" + std::to_string(at.line) + ":" + std::to_string(at.column) + ": " +
           message;
}

int YamlSource::span_of(const YAML::Node& node) const {
    const YAML::Mark mark = node.Mark();
    const std::string_view text = line(mark.line);
    if (mark.is_null() || mark.column < 0 || std::size_t(mark.column) >= text.size()) return 1;
    const std::size_t begin = std::size_t(mark.column);
    const char c = text[begin];
    if (c == '"' || c == '\'' || c == '[' || c == '{') {
        const auto end = closing(text, begin);
        return end ? int(*end - begin + 1) : 1;
    }
    if (node.IsScalar() && !node.Scalar().empty() &&
        text.substr(begin).starts_with(node.Scalar())) {
        return int(node.Scalar().size());
    }
    return 1;
}

SceneError YamlSource::error(std::string message, std::vector<std::string> notes) const {
    return SceneError({file_name_, 0, 0}, std::move(message), std::move(notes));
}

SceneError YamlSource::error_at(const YAML::Mark& mark, int span, std::string message,
                                std::vector<std::string> notes) const {
    if (mark.is_null() || mark.line < 0) return error(std::move(message), std::move(notes));
    return SceneError({file_name_, mark.line + 1, std::max(0, mark.column) + 1}, std::move(message),
                      std::move(notes), std::string(line(mark.line)), span);
}

SceneError YamlSource::error_at(const YAML::Node& node, std::string message,
                                std::vector<std::string> notes) const {
    return error_at(node.Mark(), span_of(node), std::move(message), std::move(notes));
}

void rethrow_as_scene_error(const YamlSource& source, const std::string& what) {
    try {
        throw;
    } catch (const SceneError&) {
        throw;
    } catch (const YAML::DeepRecursion& e) {
        // yaml-cpp's own message for this is "bad file".
        throw source.error_at(
            e.mark, 1,
            "invalid YAML: nesting reaches the limit of " + std::to_string(e.depth()) + " levels");
    } catch (const YAML::ParserException& e) {
        throw source.error_at(e.mark, 1, "invalid YAML: " + e.msg);
    } catch (const YAML::Exception& e) {
        // The readers avoid the calls that throw these; this is the safety net.
        throw source.error_at(e.mark, 1, "cannot read the YAML: " + e.msg);
    } catch (const std::bad_alloc&) {
        throw source.error("out of memory while reading " + what);
    } catch (const std::exception& e) {
        throw source.error("cannot read " + what + ": " + e.what());
    }
}

}  // namespace glint
