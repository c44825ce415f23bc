// PLY header parsing and a walk over the data it describes; see ply_validator.h.
#include "glint/scene/mesh/ply_validator.h"

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "glint/scene/mesh/text_lines.h"

namespace glint {

namespace {

enum class PlyType { int8, uint8, int16, uint16, int32, uint32, float32, float64 };

struct PlyProperty {
    std::string name;
    PlyType type = PlyType::float32;  // the item type for lists
    bool is_list = false;
    PlyType count_type = PlyType::uint8;
};

struct PlyElement {
    std::string name;
    long long count = 0;
    std::size_t line = 0;  // of its "element" header line, 1-based
    std::vector<PlyProperty> properties;
};

std::optional<PlyType> type_named(std::string_view name) {
    if (name == "char" || name == "int8") return PlyType::int8;
    if (name == "uchar" || name == "uint8") return PlyType::uint8;
    if (name == "short" || name == "int16") return PlyType::int16;
    if (name == "ushort" || name == "uint16") return PlyType::uint16;
    if (name == "int" || name == "int32") return PlyType::int32;
    if (name == "uint" || name == "uint32") return PlyType::uint32;
    if (name == "float" || name == "float32") return PlyType::float32;
    if (name == "double" || name == "float64") return PlyType::float64;
    return std::nullopt;
}

std::size_t size_of(PlyType t) {
    switch (t) {
        case PlyType::int8:
        case PlyType::uint8:
            return 1;
        case PlyType::int16:
        case PlyType::uint16:
            return 2;
        case PlyType::int32:
        case PlyType::uint32:
        case PlyType::float32:
            return 4;
        case PlyType::float64:
            return 8;
    }
    return 1;
}

// A value for a message: integers as such, anything else (NaN, huge) as a double.
std::string number_text(double v) {
    if (std::abs(v) < 1e15 && v == std::floor(v)) return std::to_string((long long)v);
    return std::to_string(v);
}

// List lengths are counts; a float count type could hold anything, and the cast to an integer
// is defined only in range.
bool valid_length(double n) { return n >= 0 && n < 2147483648.0 && n == std::floor(n); }

bool is_ply_magic(std::string_view three) {
    return three.size() == 3 && (three[0] | 0x20) == 'p' && (three[1] | 0x20) == 'l' &&
           (three[2] | 0x20) == 'y';
}

bool is_float(PlyType t) { return t == PlyType::float32 || t == PlyType::float64; }

bool is_face_index_list(const PlyElement& e, const PlyProperty& p) {
    return e.name == "face" && p.is_list &&
           (p.name == "vertex_indices" || p.name == "vertex_index");
}

// As for OBJ faces; Assimp's triangulation also aborts on a face of none.
std::string too_few_vertices(long long face, double length) {
    return "face " + std::to_string(face) + " has " + std::to_string((long long)length) +
           " vertices; a face needs at least 3";
}

std::string count_of(long long n, const std::string& name) {
    return std::to_string(n) + " " + name + (n == 1 ? "" : " entries");
}

class BinaryReader {
public:
    BinaryReader(std::string_view data, bool big_endian) : data_(data), big_endian_(big_endian) {}

    std::size_t remaining() const { return data_.size() - pos_; }
    // Nothing when the data ends first.
    std::optional<double> read(PlyType t) {
        const std::size_t n = size_of(t);
        if (remaining() < n) return std::nullopt;
        unsigned char b[8];
        std::memcpy(b, data_.data() + pos_, n);
        pos_ += n;
        if (big_endian_ != (std::endian::native == std::endian::big)) {
            for (std::size_t i = 0; i < n / 2; ++i) std::swap(b[i], b[n - 1 - i]);
        }
        switch (t) {
            case PlyType::int8:
                return double(std::int8_t(b[0]));
            case PlyType::uint8:
                return double(b[0]);
            case PlyType::int16:
                return double(load<std::int16_t>(b));
            case PlyType::uint16:
                return double(load<std::uint16_t>(b));
            case PlyType::int32:
                return double(load<std::int32_t>(b));
            case PlyType::uint32:
                return double(load<std::uint32_t>(b));
            case PlyType::float32:
                return double(load<float>(b));
            case PlyType::float64:
                return load<double>(b);
        }
        return std::nullopt;
    }

private:
    template <typename T>
    static T load(const unsigned char* b) {
        T v;
        std::memcpy(&v, b, sizeof v);
        return v;
    }

    std::string_view data_;
    std::size_t pos_ = 0;
    bool big_endian_;
};

class PlyValidator {
public:
    // Lines are indexed over the header only, until the data is known to be text too: binary
    // data is not split into "lines".
    PlyValidator(const std::filesystem::path& file, std::string_view bytes)
        : file_(file.string()), bytes_(bytes), lines_(header_of(bytes), file_) {}

    void run() {
        parse_header();
        if (ascii_) lines_ = TextLines(bytes_, file_);
        const std::size_t vertex = find_vertex_element();
        vertex_count_ = vertex < elements_.size() ? elements_[vertex].count : 0;
        check_counts_fit();
        if (ascii_) {
            walk_ascii();
        } else {
            walk_binary();
        }
    }

private:
    static std::string_view header_of(std::string_view bytes) {
        const std::size_t end = bytes.find("end_header");
        if (end == std::string_view::npos) return bytes;
        const std::size_t newline = bytes.find('\n', end);
        return bytes.substr(0, newline == std::string_view::npos ? bytes.size() : newline + 1);
    }

    // Assimp reads a file for PLY when it finds "ply" in any case near its start, after blank
    // lines or NULs too, and hangs or leaks on some such files: anything else is refused here.
    void parse_header() {
        if (bytes_.size() < 3 || !is_ply_magic(bytes_.substr(0, 3)) ||
            split_tokens(lines_.line(0), false)[0].text.size() != 3) {
            throw lines_.error_at(1, 1, 3, "a PLY file must start with a line \"ply\"");
        }
        bool have_format = false;
        for (std::size_t i = 1; i < lines_.size(); ++i) {
            const std::size_t n = i + 1;
            // The header is text: Assimp reads its lines as C strings, and hangs on some with a
            // NUL inside.
            if (const std::size_t nul = lines_.line(i).find('\0'); nul != std::string_view::npos)
                throw lines_.error_at(n, int(nul) + 1, 1, "the PLY header holds a NUL byte");
            // Nor a carriage return but before a line feed: Assimp ends a line there, glint
            // does not, and Assimp read out of bounds on one such header.
            if (const std::size_t cr = lines_.line(i).find('\r'); cr != std::string_view::npos)
                throw lines_.error_at(n, int(cr) + 1, 1,
                                      "the PLY header holds a carriage return that ends no line");
            const auto tokens = split_tokens(lines_.line(i), false);
            if (tokens.empty()) continue;
            const std::string_view key = tokens[0].text;
            if (key == "end_header") {
                if (!have_format) throw lines_.error_at(n, 1, 10, "PLY header has no format line");
                data_line_ = i + 1;
                const std::size_t newline = bytes_.find('\n', line_offset(i));
                // Assimp hangs on some headers that end the file (two format lines do it).
                if (newline == std::string_view::npos)
                    throw lines_.error_at(n, 1, 10,
                                          "the file ends at end_header: no line break, no data");
                data_offset_ = newline + 1;
                return;
            }
            if (key == "comment" || key == "obj_info") continue;
            if (key == "format") {
                if (have_format) throw lines_.error_at(n, 1, 6, "a second format line");
                if (tokens.size() < 2)
                    throw lines_.error_at(n, 1, 6, "format line names no format");
                const std::string_view f = tokens[1].text;
                if (f == "ascii") {
                    ascii_ = true;
                } else if (f == "binary_little_endian" || f == "binary_big_endian") {
                    big_endian_ = f == "binary_big_endian";
                } else {
                    throw lines_.error_at(n, tokens[1].column, int(f.size()),
                                          "unknown PLY format \"" + std::string(f) + "\"",
                                          {"formats are: ascii, binary_big_endian, "
                                           "binary_little_endian"});
                }
                have_format = true;
            } else if (key == "element") {
                if (tokens.size() < 3) {
                    throw lines_.error_at(n, 1, 7, "element line needs a name and a count");
                }
                const auto count = parse_integer(tokens[2].text);
                if (!count || *count < 0) {
                    throw lines_.error_at(n, tokens[2].column, int(tokens[2].text.size()),
                                          "element count must be a non-negative integer, got \"" +
                                              std::string(tokens[2].text) + "\"");
                }
                // Assimp sizes a mesh's faces by the first face element and writes every face
                // element's into it: past the end, for a second one.
                for (const PlyElement& e : elements_)
                    if (e.name == tokens[1].text)
                        throw lines_.error_at(n, tokens[1].column, int(tokens[1].text.size()),
                                              "a second element \"" + e.name +
                                                  "\" (the first is at line " +
                                                  std::to_string(e.line) + ")");
                elements_.push_back({std::string(tokens[1].text), *count, n, {}});
            } else if (key == "property") {
                if (elements_.empty()) {
                    throw lines_.error_at(n, 1, 8, "property line before any element line");
                }
                elements_.back().properties.push_back(parse_property(n, tokens));
            } else {
                throw lines_.error_at(n, tokens[0].column, int(key.size()),
                                      "unknown PLY header line \"" + std::string(key) + "\"");
            }
        }
        throw lines_.error_at(1, 1, 3, "PLY header has no end_header line");
    }

    std::size_t line_offset(std::size_t index) const {
        const std::string_view l = lines_.line(index);
        return std::size_t(l.data() - bytes_.data());
    }

    PlyProperty parse_property(std::size_t n, const std::vector<Token>& tokens) const {
        const auto type_at = [&](std::size_t k) {
            if (k >= tokens.size()) {
                throw lines_.error_at(n, 1, 8, "property line is incomplete");
            }
            const auto t = type_named(tokens[k].text);
            if (!t) {
                throw lines_.error_at(n, tokens[k].column, int(tokens[k].text.size()),
                                      "unknown PLY type \"" + std::string(tokens[k].text) + "\"");
            }
            return *t;
        };
        PlyProperty p;
        if (tokens.size() > 1 && tokens[1].text == "list") {
            p.is_list = true;
            p.count_type = type_at(2);
            p.type = type_at(3);
            if (tokens.size() < 5) throw lines_.error_at(n, 1, 8, "property line is incomplete");
            p.name = std::string(tokens[4].text);
        } else {
            p.type = type_at(1);
            if (tokens.size() < 3) throw lines_.error_at(n, 1, 8, "property line is incomplete");
            p.name = std::string(tokens[2].text);
        }
        return p;
    }

    std::size_t find_vertex_element() const {
        for (std::size_t i = 0; i < elements_.size(); ++i) {
            if (elements_[i].name == "vertex") return i;
        }
        return elements_.size();
    }

    // Every entry needs at least some bytes: its fixed-size values in binary, a character and a
    // separator per value in ASCII. Checked before anything is read, and before Assimp sizes its
    // arrays by the counts.
    void check_counts_fit() const {
        const auto available = (unsigned long long)(bytes_.size() - data_offset_);
        unsigned long long needed = 0;
        for (const PlyElement& e : elements_) {
            unsigned long long per_entry = 0;
            for (const PlyProperty& p : e.properties) {
                per_entry += ascii_ ? 2 : size_of(p.is_list ? p.count_type : p.type);
            }
            if (per_entry > 0 && (unsigned long long)e.count >
                                     (available - std::min(needed, available)) / per_entry) {
                throw lines_.error_at(e.line, 1, int(lines_.line(e.line - 1).size()),
                                      "header declares " + count_of(e.count, e.name) +
                                          ", which need at least " + std::to_string(per_entry) +
                                          " bytes each, but only " +
                                          std::to_string(available - std::min(needed, available)) +
                                          " bytes of data are left for them");
            }
            needed += per_entry * (unsigned long long)e.count;
        }
    }

    void check_index(double value, const PlyElement& e, long long entry, std::size_t line,
                     int column, int span) const {
        if (value < 0 || value >= double(vertex_count_) || value != std::floor(value)) {
            throw lines_.error_at(line, column, span,
                                  e.name + " " + std::to_string(entry) + " refers to vertex " +
                                      number_text(value) + ", but there are " +
                                      std::to_string(vertex_count_) + " vertices");
        }
    }

    void walk_ascii() const {
        std::size_t line = data_line_;  // 0-based index of the next line to read
        for (const PlyElement& e : elements_) {
            for (long long entry = 0; entry < e.count; ++entry) {
                std::vector<Token> tokens;
                while (line < lines_.size() && tokens.empty()) {
                    tokens = split_tokens(lines_.line(line++), false);
                }
                if (tokens.empty()) {
                    throw lines_.error_at(e.line, 1, int(lines_.line(e.line - 1).size()),
                                          "file ends after " + std::to_string(entry) + " of the " +
                                              count_of(e.count, e.name) + " this line declares");
                }
                check_ascii_entry(e, entry, tokens, line);
            }
        }
    }

    void check_ascii_entry(const PlyElement& e, long long entry, const std::vector<Token>& tokens,
                           std::size_t n) const {
        std::size_t k = 0;
        const auto next = [&](PlyType type, const char* what) -> std::pair<double, const Token*> {
            if (k >= tokens.size()) {
                const Token& last = tokens.back();
                throw lines_.error_at(
                    n, last.column, int(last.text.size()),
                    e.name + " " + std::to_string(entry) + " ends early: " + what +
                        " is missing (is the header's count of " + e.name + " entries right?)");
            }
            const Token& t = tokens[k++];
            const auto error = [&](const std::string& message) {
                return lines_.error_at(n, t.column, int(t.text.size()), message);
            };
            const auto expected = [&](const char* kind) {
                return error(std::string("expected ") + kind + " for " + what + ", got \"" +
                             std::string(t.text) + "\"");
            };
            if (is_float(type)) {
                const auto value = parse_float(t.text);
                if (!value) throw expected("a number");
                if (!std::isfinite(*value))
                    throw error(e.name + " " + std::to_string(entry) +
                                " has a value that is not finite: \"" + std::string(t.text) + "\"");
                return {double(*value), &t};
            }
            const auto integer = parse_integer(t.text);
            if (!integer) throw expected("an integer");
            return {double(*integer), &t};
        };
        for (const PlyProperty& p : e.properties) {
            if (!p.is_list) {
                next(p.type, p.name.c_str());
                continue;
            }
            const auto [length, at] = next(p.count_type, ("the length of " + p.name).c_str());
            if (!valid_length(length)) {
                throw lines_.error_at(n, at->column, int(at->text.size()),
                                      "list length must be a whole number in [0, 2^31)");
            }
            if (is_face_index_list(e, p) && length < 3) {
                throw lines_.error_at(n, at->column, int(at->text.size()),
                                      too_few_vertices(entry, length));
            }
            for (long long i = 0; i < (long long)length; ++i) {
                const auto [value, token] = next(p.type, p.name.c_str());
                if (is_face_index_list(e, p)) {
                    check_index(value, e, entry, n, token->column, int(token->text.size()));
                }
            }
        }
        if (k < tokens.size()) {
            throw lines_.error_at(
                n, tokens[k].column, int(tokens[k].text.size()),
                e.name + " " + std::to_string(entry) + " has " + std::to_string(tokens.size()) +
                    " values, more than its " + std::to_string(k) +
                    " properties take (is the header's count of " + e.name + " entries right?)");
        }
    }

    void walk_binary() const {
        BinaryReader reader(bytes_.substr(data_offset_), big_endian_);
        for (const PlyElement& e : elements_) {
            const int span = int(lines_.line(e.line - 1).size());
            const auto truncated = [&](long long entry) {
                return lines_.error_at(e.line, 1, span,
                                       "binary data ends in entry " + std::to_string(entry) +
                                           " of the " + count_of(e.count, e.name) +
                                           " this line declares (the file is truncated)");
            };
            for (long long entry = 0; entry < e.count; ++entry) {
                for (const PlyProperty& p : e.properties) {
                    if (!p.is_list) {
                        const auto v = reader.read(p.type);
                        if (!v) throw truncated(entry);
                        if (!std::isfinite(*v)) {
                            throw lines_.error_at(e.line, 1, span,
                                                  e.name + " " + std::to_string(entry) +
                                                      " has a value that is not finite in " +
                                                      p.name);
                        }
                        continue;
                    }
                    const auto length = reader.read(p.count_type);
                    if (!length) throw truncated(entry);
                    if (!valid_length(*length)) {
                        throw lines_.error_at(e.line, 1, span,
                                              e.name + " " + std::to_string(entry) +
                                                  " has a list length that is not a whole number "
                                                  "in [0, 2^31)");
                    }
                    if (is_face_index_list(e, p) && *length < 3) {
                        throw lines_.error_at(e.line, 1, span, too_few_vertices(entry, *length));
                    }
                    for (long long i = 0; i < (long long)*length; ++i) {
                        const auto v = reader.read(p.type);
                        if (!v) throw truncated(entry);
                        if (is_face_index_list(e, p)) check_index(*v, e, entry, e.line, 1, span);
                    }
                }
            }
        }
    }

    std::string file_;
    std::string_view bytes_;
    TextLines lines_;
    std::vector<PlyElement> elements_;
    bool ascii_ = false;
    bool big_endian_ = false;
    std::size_t data_line_ = 0;    // 0-based index of the first line after end_header
    std::size_t data_offset_ = 0;  // byte offset of the data
    long long vertex_count_ = 0;
};

}  // namespace

void validate_ply(const std::filesystem::path& file, std::string_view bytes) {
    PlyValidator(file, bytes).run();
}

}  // namespace glint
