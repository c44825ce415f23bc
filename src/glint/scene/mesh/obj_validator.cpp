// Line-by-line OBJ and MTL checks with file:line:col errors; see obj_validator.h.
#include "glint/scene/mesh/obj_validator.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "glint/scene/mesh/mesh_limits.h"
#include "glint/scene/mesh/text_lines.h"

namespace glint {

namespace {

struct Counts {
    long long v = 0, vt = 0, vn = 0;
};

// Built by appending: GCC 12's -Wrestrict misfires on "\"" + std::string (GCC bug 105651).
std::string in_quotes(std::string_view s) {
    std::string out;
    out.reserve(s.size() + 2);
    out += '"';
    out += s;
    out += '"';
    return out;
}

// Checks that tokens [first, first + count) are finite numbers; `what` names the line's kind.
void check_numbers(const TextLines& lines, std::size_t line, const std::vector<Token>& tokens,
                   std::size_t first, std::size_t count, std::string_view what) {
    if (tokens.size() < first + count) {
        const Token& last = tokens.back();
        throw lines.error_at(line, last.column, int(last.text.size()),
                             std::string(what) + " needs " + std::to_string(count) +
                                 " numbers, got " + std::to_string(tokens.size() - first));
    }
    for (std::size_t i = first; i < tokens.size(); ++i) {
        const Token& t = tokens[i];
        const auto value = parse_float(t.text);
        if (!value) {
            // Extra words after the numbers are tolerated only past the required ones, as
            // writers append comments without '#'; a word in a required place is an error.
            if (i >= first + count) break;
            throw lines.error_at(line, t.column, int(t.text.size()),
                                 "expected a number, got " + in_quotes(t.text));
        }
        if (!std::isfinite(*value)) {
            throw lines.error_at(
                line, t.column, int(t.text.size()),
                std::string(what) + " has a number that is not finite: " + in_quotes(t.text));
        }
    }
}

// One index of a corner ("12", "-1") of an element ("face", "line", "point"); kind is "vertex",
// "texture coordinate" or "normal".
void check_index(const TextLines& lines, std::size_t line, std::string_view text, int column,
                 std::string_view element, const char* kind, long long preceding, long long total) {
    const auto index = parse_integer(text);
    const int span = std::max(1, int(text.size()));
    if (!index) {
        throw lines.error_at(line, column, span,
                             "expected a " + std::string(kind) + " index, got " + in_quotes(text));
    }
    if (*index == 0) {
        throw lines.error_at(line, column, span,
                             std::string(kind) + " index 0 is invalid: OBJ indices start at 1");
    }
    if (*index > total) {
        throw lines.error_at(line, column, span,
                             std::string(element) + " refers to " + std::string(kind) + " " +
                                 std::to_string(*index) + ", but the file has " +
                                 std::to_string(total));
    }
    if (*index < 0 && -*index > preceding) {
        throw lines.error_at(line, column, span,
                             std::string(element) + " refers to " + std::string(kind) + " " +
                                 std::to_string(*index) + " (counted back), but only " +
                                 std::to_string(preceding) + " come before it");
    }
}

// A face (f), polyline (l) or point set (p): its corners' indices, and at least 3 for a face, 2
// for a line and 1 for points (Assimp makes a mesh of none of a material's elements with fewer,
// throws, and leaks it).
void check_element(const TextLines& lines, std::size_t line, const std::vector<Token>& tokens,
                   const Counts& before, const Counts& total) {
    const char kind = tokens[0].text.front();
    const std::string_view element = kind == 'f' ? "face" : kind == 'l' ? "line" : "point";
    const std::size_t least = kind == 'f' ? 3 : kind == 'l' ? 2 : 1;
    if (tokens.size() - 1 < least) {
        const Token& last = tokens.back();
        throw lines.error_at(line, tokens.front().column,
                             last.column + int(last.text.size()) - tokens.front().column,
                             std::string(element) + " has " + std::to_string(tokens.size() - 1) +
                                 (tokens.size() == 2 ? " vertex" : " vertices") + "; a " +
                                 std::string(element) + " needs at least " + std::to_string(least));
    }
    for (std::size_t i = 1; i < tokens.size(); ++i) {
        const Token& t = tokens[i];
        // v, v/vt, v//vn or v/vt/vn.
        std::size_t start = 0;
        for (int part = 0; part < 3 && start <= t.text.size(); ++part) {
            std::size_t slash = t.text.find('/', start);
            if (slash == std::string_view::npos) slash = t.text.size();
            const std::string_view index = t.text.substr(start, slash - start);
            const int column = t.column + int(start);
            if (part == 0 || !index.empty()) {
                static const char* kinds[] = {"vertex", "texture coordinate", "normal"};
                const long long preceding[] = {before.v, before.vt, before.vn};
                const long long totals[] = {total.v, total.vt, total.vn};
                check_index(lines, line, index, column, element, kinds[part], preceding[part],
                            totals[part]);
            }
            if (slash == t.text.size()) break;
            start = slash + 1;
            if (part == 2) {
                throw lines.error_at(line, t.column, int(t.text.size()),
                                     std::string(element) + " corner " + in_quotes(t.text) +
                                         " has more than 3 parts");
            }
        }
    }
}

// The file a statement names: the rest of the line, or with options ("-s 1 1 1 name") the last
// token.
std::pair<std::string, Token> named_file(const std::vector<Token>& tokens, std::string_view line) {
    const Token& first = tokens[1];
    const bool options = first.text.starts_with("-");
    if (options) return {std::string(tokens.back().text), tokens.back()};
    std::string_view rest = line.substr(std::size_t(first.column - 1));
    while (!rest.empty() && (rest.back() == ' ' || rest.back() == '\t')) rest.remove_suffix(1);
    return {std::string(rest), Token{rest, first.column}};
}

bool is_file(const std::filesystem::path& p) {
    std::error_code ec;
    return std::filesystem::is_regular_file(p, ec);
}

// Refuses a file the line names outside the sandbox, at its token, before anything looks for it.
void check_sandbox(const TextLines& lines, std::size_t line, const Token& token,
                   const ReadSandbox& sandbox, const std::filesystem::path& path,
                   std::string_view what, const std::string& name) {
    if (const auto refusal = check_read(sandbox, path, what, name)) {
        throw lines.error_at(line, token.column, int(token.text.size()), refusal->message,
                             refusal->notes);
    }
}

}  // namespace

std::vector<std::string> validate_mtl(const std::filesystem::path& file, std::string_view text,
                                      const ReadSandbox& sandbox) {
    const TextLines lines(text, file.string(), LineBreaks::obj);
    std::vector<std::string> names;
    bool in_material = false;
    for (std::size_t i = 0; i < lines.size(); ++i) {
        const std::string_view line = lines.line(i);
        const auto tokens = split_tokens(line);
        if (tokens.empty()) continue;
        const std::string_view key = tokens[0].text;
        const std::size_t n = i + 1;
        if (key == "newmtl") {
            in_material = true;
        } else if (!in_material) {
            // Assimp applies some statements to a material that does not exist yet, and
            // crashes ("bump" does).
            throw lines.error_at(n, tokens[0].column, int(key.size()),
                                 in_quotes(key) + " comes before any newmtl",
                                 {"a material's statements follow the newmtl line that names it"});
        }
        if (key == "newmtl" && tokens.size() > 1) {
            names.emplace_back(named_file(tokens, line).first);
        } else if (key == "Kd" || key == "Ka" || key == "Ks" || key == "Ke" || key == "Tf") {
            if (tokens.size() > 1 && (tokens[1].text == "spectral" || tokens[1].text == "xyz")) {
                continue;  // forms Assimp ignores
            }
            check_numbers(lines, n, tokens, 1, 1, key);
        } else if (key == "Ns" || key == "Ni" || key == "d" || key == "Tr") {
            check_numbers(lines, n, tokens, 1, 1, key);
        } else if (key == "map_Kd" || key == "map_kd") {
            if (tokens.size() < 2) {
                throw lines.error_at(n, tokens[0].column, 6, "map_Kd names no texture file");
            }
            const auto [name, token] = named_file(tokens, line);
            const std::filesystem::path texture = file.parent_path() / name;
            check_sandbox(lines, n, token, sandbox, texture, "texture file", name);
            if (!is_file(texture)) {
                throw lines.error_at(n, token.column, int(token.text.size()),
                                     "texture file " + in_quotes(name) + " not found",
                                     {"looked for " + texture.string()});
            }
        }
    }
    return names;
}

ObjCheck validate_obj(const std::filesystem::path& file, std::string_view text,
                      const ReadSandbox& sandbox) {
    const TextLines lines(text, file.string(), LineBreaks::obj);
    // Positive indices may point forwards (Assimp resolves them after reading), so the totals
    // come first.
    Counts total;
    for (std::size_t i = 0; i < lines.size(); ++i) {
        const std::string_view line = lines.line(i);
        if (line.starts_with("v ") || line.starts_with("v\t")) ++total.v;
        if (line.starts_with("vt ") || line.starts_with("vt\t")) ++total.vt;
        if (line.starts_with("vn ") || line.starts_with("vn\t")) ++total.vn;
    }

    ObjCheck result;
    std::vector<std::string> materials;
    long long faces = 0;
    Counts before;
    for (std::size_t i = 0; i < lines.size(); ++i) {
        const std::string_view line = lines.line(i);
        const auto tokens = split_tokens(line);
        if (tokens.empty()) continue;
        const std::string_view key = tokens[0].text;
        const std::size_t n = i + 1;
        if (key == "v") {
            check_numbers(lines, n, tokens, 1, 3, "vertex");
            ++before.v;
        } else if (key == "vt") {
            check_numbers(lines, n, tokens, 1, 1, "texture coordinate");
            ++before.vt;
        } else if (key == "vn") {
            check_numbers(lines, n, tokens, 1, 3, "normal");
            ++before.vn;
        } else if (key.front() == 'f' || key.front() == 'l' || key.front() == 'p') {
            // Assimp reads every line that starts with f, l or p as a face, polyline or points
            // ("f1 2 3" and "lod 2" too), and leaks what it built when an index is out of range.
            check_element(lines, n, tokens, before, total);
            if (key.front() == 'f') ++faces;
        } else if (key == "mtllib") {
            if (tokens.size() < 2) {
                throw lines.error_at(n, tokens[0].column, 6, "mtllib names no file");
            }
            // Assimp takes the rest of the line as one name; several names are also accepted.
            const auto [name, token] = named_file(tokens, line);
            std::vector<std::pair<std::string, Token>> libraries;
            const std::filesystem::path whole = file.parent_path() / name;
            if ((may_read(sandbox, whole) && is_file(whole)) || tokens.size() == 2) {
                libraries.push_back({name, token});
            } else {
                for (std::size_t k = 1; k < tokens.size(); ++k) {
                    libraries.push_back({std::string(tokens[k].text), tokens[k]});
                }
            }
            for (const auto& [library, at] : libraries) {
                const std::filesystem::path path = file.parent_path() / library;
                check_sandbox(lines, n, at, sandbox, path, "material library", library);
                if (!is_file(path)) {
                    throw lines.error_at(n, at.column, int(at.text.size()),
                                         "material library " + in_quotes(library) + " not found",
                                         {"looked for " + path.string()});
                }
                const std::string mtl =
                    read_text_file(path.string(), sandbox.file_limit(kMaxMeshFileBytes));
                const auto names = validate_mtl(path, mtl, sandbox);
                result.material_libraries.push_back(path);
                materials.insert(materials.end(), names.begin(), names.end());
            }
        } else if (key == "usemtl" && tokens.size() > 1) {
            const std::string name = named_file(tokens, line).first;
            auto& unknown = result.undefined_materials;
            if (std::find(materials.begin(), materials.end(), name) == materials.end() &&
                std::find(unknown.begin(), unknown.end(), name) == unknown.end()) {
                unknown.push_back(name);
                result.warnings.push_back(
                    file.string() + ":" + std::to_string(n) + ": usemtl " + in_quotes(name) +
                    " names a material no mtllib defines; it gets glint's default "
                    "material");
            }
        }
    }
    if (faces == 0) {
        throw SceneError({file.string(), 0, 0}, "the file has no faces (no f lines)",
                         {"points and lines are not surfaces; glint renders triangles"});
    }
    return result;
}

}  // namespace glint
