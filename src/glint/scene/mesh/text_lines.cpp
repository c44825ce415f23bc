// Lines, tokens and numbers of text mesh files, with located errors.
#include "glint/scene/mesh/text_lines.h"

#include <cerrno>
#include <charconv>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <system_error>

#include "glint/scene/read_sandbox.h"

namespace glint {

namespace {
bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; }
}  // namespace

std::vector<Token> split_tokens(std::string_view line, bool hash_comments) {
    std::vector<Token> tokens;
    std::size_t i = 0;
    while (i < line.size()) {
        while (i < line.size() && is_blank(line[i])) ++i;
        if (i == line.size() || (hash_comments && line[i] == '#')) break;
        const std::size_t start = i;
        while (i < line.size() && !is_blank(line[i])) ++i;
        tokens.push_back({line.substr(start, i - start), int(start) + 1});
    }
    return tokens;
}

TextLines::TextLines(std::string_view text, std::string file_name, LineBreaks breaks)
    : text_(text), file_name_(std::move(file_name)) {
    const std::string_view ends =
        breaks == LineBreaks::obj ? std::string_view("\n\r\f\0", 4) : std::string_view("\n");
    std::size_t start = 0;
    while (start < text.size()) {
        starts_.push_back(start);
        const std::size_t end = text.find_first_of(ends, start);
        if (end == std::string_view::npos) {
            ends_.push_back(text.size());
            break;
        }
        ends_.push_back(end);
        const bool crlf = text[end] == '\r' && end + 1 < text.size() && text[end + 1] == '\n';
        start = end + (crlf ? 2 : 1);  // "\r\n" is one break
    }
}

std::string_view TextLines::line(std::size_t index) const {
    if (index >= starts_.size()) return {};
    std::size_t end = ends_[index];
    if (end > starts_[index] && text_[end - 1] == '\r') --end;  // of "\r\n" under "\n" breaks
    return text_.substr(starts_[index], end - starts_[index]);
}

SceneError TextLines::error_at(std::size_t line_number, int column, int span, std::string message,
                               std::vector<std::string> notes) const {
    std::string quoted(line_number > 0 ? line(line_number - 1) : std::string_view{});
    // Long lines (a binary file read as text) are cut so that the quote stays readable.
    if (quoted.size() > 200) quoted.resize(200);
    for (char& c : quoted) {
        if (static_cast<unsigned char>(c) < 32 && c != '\t') c = '?';
    }
    return SceneError({file_name_, int(line_number), column}, std::move(message), std::move(notes),
                      std::move(quoted), span);
}

std::optional<float> parse_float(std::string_view token) {
    if (token.empty()) return std::nullopt;
    // from_chars rejects a leading '+', which OBJ writers emit.
    if (token.front() == '+') token.remove_prefix(1);
    float value = 0;
    const auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), value);
    if (end != token.data() + token.size()) return std::nullopt;
    if (ec == std::errc::result_out_of_range) {
        // Too large for a float: report it as the infinity it would become.
        return token.front() == '-' ? -std::numeric_limits<float>::infinity()
                                    : std::numeric_limits<float>::infinity();
    }
    if (ec != std::errc()) return std::nullopt;
    return value;
}

std::optional<long long> parse_integer(std::string_view token) {
    if (!token.empty() && token.front() == '+') token.remove_prefix(1);
    long long value = 0;
    const auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), value);
    if (ec != std::errc() || end != token.data() + token.size() || token.empty()) {
        return std::nullopt;
    }
    return value;
}

std::string read_text_file(const std::string& file, std::uintmax_t max_bytes) {
    std::error_code ec;
    const auto size = std::filesystem::file_size(file, ec);
    if (ec) throw SceneError({file, 0, 0}, "cannot read file: " + ec.message());
    if (size > max_bytes) {
        throw SceneError({file, 0, 0},
                         "file is " + std::to_string(size) + " bytes, more than the limit of " +
                             describe_file_limit(max_bytes),
                         {kRaiseFileLimitNote});
    }
    std::ifstream in(file, std::ios::binary);
    std::string text(size, '\0');
    if (!in || !in.read(text.data(), std::streamsize(size))) {
        throw SceneError({file, 0, 0}, std::string("cannot read file: ") + std::strerror(errno));
    }
    return text;
}

}  // namespace glint
