// POV-Ray's file directives without touching the disk for writing: #write keeps its text in
// memory by the file's name, where #read and #include find it again; #read reads files the
// scene may read (its folder, the include folders, the sandbox) or the ones it wrote.
#include <cctype>
#include <cstdlib>

#include "glint/scene/pov/pov_parser.h"
#include "glint/scene/quote.h"

namespace glint {

namespace {

// The whole text a scene may write, over all its files.
constexpr std::size_t kMaxWrittenBytes = std::size_t(1) << 24;

// The next value of POV-Ray's data format (a float, a "string" or a <vector>, separated by
// commas) from `text` at `at`; nothing at the end of the text.
std::optional<PovValue> next_datum(const std::string& text, std::size_t& at, bool& malformed) {
    const auto skip = [&] {
        while (at < text.size() &&
               (std::isspace(static_cast<unsigned char>(text[at])) || text[at] == ','))
            ++at;
    };
    const auto number = [&]() -> std::optional<double> {
        const char* start = text.c_str() + at;
        char* end = nullptr;
        const double value = std::strtod(start, &end);
        if (end == start) return std::nullopt;
        at += std::size_t(end - start);
        return value;
    };
    skip();
    if (at >= text.size()) return std::nullopt;
    if (text[at] == '"') {
        const std::size_t close = text.find('"', at + 1);
        if (close == std::string::npos) {
            malformed = true;
            return std::nullopt;
        }
        std::string s = text.substr(at + 1, close - at - 1);
        at = close + 1;
        return PovValue{std::move(s)};
    }
    if (text[at] == '<') {
        ++at;
        PovVector v;
        v.size = 0;
        for (;;) {
            skip();
            if (at < text.size() && text[at] == '>') break;
            const auto component = number();
            if (!component || v.size == 5) {
                malformed = true;
                return std::nullopt;
            }
            v[v.size++] = *component;
        }
        ++at;
        if (v.size < 2) {
            malformed = true;
            return std::nullopt;
        }
        return PovValue{v};
    }
    if (const auto value = number()) return PovValue{*value};
    malformed = true;
    return std::nullopt;
}

// What #write puts in the file for a value: a string as it is, numbers as the shortest text
// that reads back the same, vectors in angle brackets.
std::string written_text(const PovValue& value) {
    if (const auto* s = std::get_if<std::string>(&value)) return *s;
    if (const auto* d = std::get_if<double>(&value)) return format_pov_number(*d);
    if (const auto* v = std::get_if<PovVector>(&value)) {
        std::string out = "<";
        for (int i = 0; i < v->size; ++i) out += (i ? "," : "") + format_pov_number((*v)[i]);
        return out + ">";
    }
    return "";
}

}  // namespace

void PovParser::fopen_directive(const PovToken& directive) {
    const PovToken handle = next();
    if (handle.kind != PovTokenKind::identifier)
        throw error_at(handle, "expected a file handle after #fopen, got " + describe(handle));
    const PovToken name_token = peek();
    const std::string name = string_expression("after #fopen's handle");
    const PovToken mode = next();
    OpenFile file;
    file.name = name;
    if (mode.is_word("write") || mode.is_word("append")) {
        file.writing = true;
        std::string& text = written_[name];
        if (mode.is_word("write")) {
            written_bytes_ -= text.size();
            text.clear();
        }
    } else if (mode.is_word("read")) {
        file.text = read_file(directive, name_token, name, "file").second;
    } else {
        throw error_at(
            mode, "expected read, write or append after #fopen's file name, got " + describe(mode));
    }
    open_files_[handle.text] = std::move(file);
}

void PovParser::fclose_directive(const PovToken&) {
    const PovToken handle = next();
    if (handle.kind != PovTokenKind::identifier || !open_files_.erase(handle.text))
        throw error_at(handle,
                       describe(handle) + " is not an open file, so #fclose cannot close it");
}

void PovParser::write_directive(const PovToken&) {
    expect("(", "after #write");
    const PovToken handle = next();
    const auto file = open_files_.find(handle.text);
    if (file == open_files_.end() || !file->second.writing)
        throw error_at(handle, describe(handle) + " is not a file open for writing");
    accept(",");
    std::string& text = written_[file->second.name];
    do {
        const PovToken at = peek();
        const std::string item = written_text(expression());
        written_bytes_ += item.size();
        if (written_bytes_ > kMaxWrittenBytes)
            throw error_at(at, "the scene writes more than " + std::to_string(kMaxWrittenBytes) +
                                   " bytes with #write");
        text += item;
    } while (accept(","));
    expect(")", "after #write's values");
}

void PovParser::read_directive(const PovToken&) {
    expect("(", "after #read");
    const PovToken handle = next();
    const auto found = open_files_.find(handle.text);
    if (found == open_files_.end() || found->second.writing)
        throw error_at(handle, describe(handle) + " is not a file open for reading");
    OpenFile& file = found->second;
    accept(",");
    do {
        const PovToken name = next();
        if (name.kind != PovTokenKind::identifier)
            throw error_at(name, "expected a variable to #read into, got " + describe(name));
        bool malformed = false;
        auto value = next_datum(file.text, file.at, malformed);
        if (malformed)
            throw error_at(name, "cannot read a value for " + quote(name.text) + " from " +
                                     quote(file.name) +
                                     ": expected a number, a \"string\" or "
                                     "a <vector>");
        // At the end of the file the variables are left undefined, and the handle too: a
        // #while (defined(Handle)) loop ends.
        if (!value) {
            file.at_end = true;
            continue;
        }
        symbols_.declare(name.text, std::move(*value));
    } while (accept(","));
    expect(")", "after #read's variables");
    bool malformed = false;
    std::size_t ahead = file.at;
    if (!next_datum(file.text, ahead, malformed) && !malformed) file.at_end = true;
}

}  // namespace glint
