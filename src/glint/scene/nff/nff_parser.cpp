// The NFF parser: a loop over entity keywords, each entity read as a run of tokens and checked
// value by value, so that an error points at the token that is wrong. Sizes are bounded before
// memory is taken for them. Large files are read in pieces on all threads.
#include "glint/scene/nff/nff_parser.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <new>
#include <optional>
#include <utility>
#include <vector>

#include "glint/geometry/polygon.h"
#include "glint/scene/gzip_file.h"
#include "glint/scene/nff/nff_tokenizer.h"
#include "glint/scene/nff/nff_view.h"
#include "glint/scene/suggest.h"

namespace glint {

namespace {

constexpr std::string_view kEntities[] = {"b", "c", "f", "l", "p", "pp", "s", "v"};
constexpr const char* kEntityList =
    "NFF entities are: b (background), c (cone or cylinder), f (material), l (light), "
    "p (polygon), pp (polygonal patch), s (sphere), v (view)";

// What other formats call the entities, for a note when one of them is written out.
struct LongName {
    std::string_view name, keyword;
};
constexpr LongName kLongNames[] = {
    {"background", "b"}, {"camera", "v"},   {"cone", "c"},     {"cylinder", "c"},
    {"light", "l"},      {"material", "f"}, {"patch", "pp"},   {"polygon", "p"},
    {"sphere", "s"},     {"surface", "f"},  {"triangle", "p"}, {"view", "v"},
};

bool looks_like_number(std::string_view text) {
    const char c = text.empty() ? ' ' : text[0];
    return (c >= '0' && c <= '9') || c == '-' || c == '+' || c == '.';
}

std::string line_note(std::string_view what, const NffToken& token) {
    return std::string(what) + " is at line " + std::to_string(token.line);
}

// The material of objects that a piece of a file (parse_in_pieces) reads before its first "f":
// the last one of the pieces before it.
constexpr std::uint32_t kInheritedMaterial = 0xffffffffu;

class NffParser {
public:
    // A parser of a piece after the first gives the objects before its first "f" the material
    // kInheritedMaterial rather than calling them an error.
    NffParser(std::string_view text, const std::string& file_name, std::int64_t max_pixels,
              bool inherits_material = false)
        : tokens_(text, file_name), max_pixels_(max_pixels), inherits_material_(inherits_material) {
        scene_.file_name = file_name;
        // The SPD's files take 10 to 100 bytes per object; the vector grows if there are more.
        scene_.objects.reserve(text.size() / 64);
    }

    NffScene parse() {
        for (NffToken keyword = tokens_.next(); !keyword.at_end(); keyword = tokens_.next()) {
            const std::string_view k = keyword.text;
            if (k == "s") {
                sphere(keyword);
            } else if (k == "p") {
                polygon(keyword);
            } else if (k == "pp") {
                patch(keyword);
            } else if (k == "c") {
                cone(keyword);
            } else if (k == "f") {
                material(keyword);
            } else if (k == "l") {
                light(keyword);
            } else if (k == "b") {
                background(keyword);
            } else if (k == "v") {
                view(keyword);
            } else {
                unknown_entity(keyword);
            }
            previous_ = keyword;
        }
        return std::move(scene_);
    }

private:
    Point3 point(const NffEntity& e, const char* x, const char* y, const char* z,
                 std::uint32_t vertex = 0) {
        const float px = tokens_.number(e, {x, vertex});
        const float py = tokens_.number(e, {y, vertex});
        return {px, py, tokens_.number(e, {z, vertex})};
    }

    float non_negative(const NffEntity& e, const NffField& field) {
        const NffToken token = tokens_.require(e, field);
        const float value = tokens_.number_of(token, e, field);
        if (value < 0) {
            throw tokens_.error_at(token, describe(e, field) + " must not be negative, got " +
                                              std::string(token.text));
        }
        return value;
    }

    Color color(const NffEntity& e) {
        const float r = non_negative(e, {"red"});
        const float g = non_negative(e, {"green"});
        return {r, g, non_negative(e, {"blue"})};
    }

    std::uint32_t object_material(const NffEntity& e) const {
        if (scene_.materials.empty() && inherits_material_) return kInheritedMaterial;
        if (scene_.materials.empty()) {
            throw tokens_.error_at(
                e.keyword,
                "a " + std::string(e.name) + " before any material: an \"f\" line must come first",
                {"\"f r g b Kd Ks Shine T ior\" sets the material of the objects after it"});
        }
        return std::uint32_t(scene_.materials.size() - 1);
    }

    void sphere(const NffToken& keyword) {
        const NffEntity e{"sphere", keyword};
        const std::uint32_t material = object_material(e);
        NffSphere s;
        s.center = point(e, "center x", "center y", "center z");
        const NffToken r = tokens_.require(e, {"radius"});
        s.radius = tokens_.number_of(r, e, {"radius"});
        // The SPD's README: "A negative radius means only the inside is visible".
        s.inside_only = s.radius < 0;
        s.radius = std::abs(s.radius);
        if (s.radius == 0) {
            throw tokens_.error_at(r,
                                   "the sphere's radius must be > 0, got " + std::string(r.text));
        }
        scene_.objects.push_back({s, material, keyword.location()});
    }

    void cone(const NffToken& keyword) {
        const NffEntity e{"cone", keyword};
        const std::uint32_t material = object_material(e);
        NffCone c;
        c.base = point(e, "base x", "base y", "base z");
        const NffToken base_radius = tokens_.require(e, {"base radius"});
        c.base_radius = tokens_.number_of(base_radius, e, {"base radius"});
        c.apex = point(e, "apex x", "apex y", "apex z");
        const NffToken apex_radius = tokens_.require(e, {"apex radius"});
        c.apex_radius = tokens_.number_of(apex_radius, e, {"apex radius"});
        // The SPD's README: "Negative radii mean only the inside is visible": both of them,
        // or one beside a pointed end.
        if ((c.base_radius < 0 && c.apex_radius > 0) || (c.base_radius > 0 && c.apex_radius < 0)) {
            const NffToken& negative = c.base_radius < 0 ? base_radius : apex_radius;
            throw tokens_.error_at(negative,
                                   "the cone's radii have opposite signs: negative radii, which "
                                   "make a cone visible from inside only, must both be negative "
                                   "(or 0)");
        }
        c.inside_only = c.base_radius < 0 || c.apex_radius < 0;
        c.base_radius = std::abs(c.base_radius);
        c.apex_radius = std::abs(c.apex_radius);
        if (c.base_radius == 0 && c.apex_radius == 0) {
            throw tokens_.error_at(apex_radius, "the cone's radii are both 0: it has no surface");
        }
        if (c.base == c.apex) {
            throw tokens_.error_at(keyword,
                                   "the cone's base and apex are the same point: it has no axis");
        }
        scene_.objects.push_back({c, material, keyword.location()});
    }

    // The vertex count of a polygon or patch, bounded before any memory is taken for it: by the
    // limit, and by what the rest of the file can hold (numbers of at least one character, each
    // after at least one space).
    std::size_t vertex_count(const NffEntity& e, int numbers_per_vertex) {
        const NffToken token = tokens_.require(e, {"vertex count"});
        const std::int64_t n = tokens_.integer_of(token, e, {"vertex count"});
        const std::string name(e.name), count(token.text);
        if (n < 3) {
            throw tokens_.error_at(token, "a " + name + " needs at least 3 vertices, got " + count);
        }
        if (n > kMaxNffPolygonVertices) {
            throw tokens_.error_at(token, "a " + name + " of " + count +
                                              " vertices is beyond the limit of " +
                                              std::to_string(kMaxNffPolygonVertices));
        }
        const std::uint64_t least = std::uint64_t(n) * std::uint64_t(2 * numbers_per_vertex);
        if (least > tokens_.remaining_bytes()) {
            throw tokens_.error_at(token,
                                   "the " + name + " claims " + count +
                                       " vertices, more than the rest of the file can hold",
                                   {"each vertex takes " + std::to_string(numbers_per_vertex) +
                                    " numbers; the file has " +
                                    std::to_string(tokens_.remaining_bytes()) + " bytes left"});
        }
        return std::size_t(n);
    }

    // Reads a vertex position, remembering where it starts for errors about it.
    Point3 vertex(const NffEntity& e, std::uint32_t index) {
        const NffToken x = tokens_.require(e, {"x", index});
        vertex_tokens_.push_back(x);
        const float px = tokens_.number_of(x, e, {"x", index});
        const float py = tokens_.number(e, {"y", index});
        return {px, py, tokens_.number(e, {"z", index})};
    }

    // At least 3 distinct vertices, an area, and coplanar (polygon_problem).
    void check_polygon(const NffEntity& e, const std::vector<Point3>& vertices) const {
        const Point3 a = vertices[0];
        const auto b = std::find_if(vertices.begin(), vertices.end(),
                                    [&](const Point3& p) { return !(p == a); });
        const auto c =
            b == vertices.end() ? b : std::find_if(b, vertices.end(), [&](const Point3& p) {
                return !(p == a) && !(p == *b);
            });
        if (c == vertices.end()) {
            throw tokens_.error_at(
                e.keyword, "the " + std::string(e.name) + " has fewer than 3 distinct vertices");
        }
        if (const auto problem = polygon_problem(vertices)) {
            const NffToken& at = problem->vertex ? vertex_tokens_[*problem->vertex] : e.keyword;
            throw tokens_.error_at(at, problem->message);
        }
    }

    void polygon(const NffToken& keyword) {
        const NffEntity e{"polygon", keyword};
        const std::uint32_t material = object_material(e);
        const std::size_t n = vertex_count(e, 3);
        NffPolygon p;
        p.vertices.reserve(n);
        vertex_tokens_.clear();
        for (std::size_t i = 0; i < n; ++i) p.vertices.push_back(vertex(e, std::uint32_t(i + 1)));
        check_polygon(e, p.vertices);
        scene_.objects.push_back({std::move(p), material, keyword.location()});
    }

    void patch(const NffToken& keyword) {
        const NffEntity e{"patch", keyword};
        const std::uint32_t material = object_material(e);
        const std::size_t n = vertex_count(e, 6);
        NffPatch p;
        p.vertices.reserve(n);
        p.normals.reserve(n);
        vertex_tokens_.clear();
        for (std::size_t i = 0; i < n; ++i) {
            const auto index = std::uint32_t(i + 1);
            p.vertices.push_back(vertex(e, index));
            const NffToken nx = tokens_.require(e, {"normal x", index});
            const float x = tokens_.number_of(nx, e, {"normal x", index});
            const float y = tokens_.number(e, {"normal y", index});
            const Normal3 normal{x, y, tokens_.number(e, {"normal z", index})};
            if (normal == Normal3{}) {
                throw tokens_.error_at(nx, "the patch's vertex " + std::to_string(index) +
                                               " normal is zero, so it has no direction");
            }
            p.normals.push_back(normal);
        }
        check_polygon(e, p.vertices);
        scene_.objects.push_back({std::move(p), material, keyword.location()});
    }

    void material(const NffToken& keyword) {
        const NffEntity e{"material", keyword};
        NffMaterial m;
        m.location = keyword.location();
        m.color = color(e);
        m.kd = non_negative(e, {"Kd"});
        m.ks = non_negative(e, {"Ks"});
        m.shine = non_negative(e, {"Shine"});
        m.transmittance = non_negative(e, {"T"});
        const NffToken ior = tokens_.require(e, {"index of refraction"});
        m.ior = tokens_.number_of(ior, e, {"index of refraction"});
        // The SPD writes 0 for opaque materials, where the index does not matter.
        if (m.ior < 0 || (m.transmittance > 0 && m.ior == 0)) {
            throw tokens_.error_at(ior,
                                   "the material's index of refraction must be > 0 when it "
                                   "transmits light (T > 0), got " +
                                       std::string(ior.text));
        }
        scene_.materials.push_back(m);
    }

    void light(const NffToken& keyword) {
        const NffEntity e{"light", keyword};
        NffLight l;
        l.location = keyword.location();
        l.position = point(e, "x", "y", "z");
        // The colour is optional: numbers after the position are it; a keyword is the next entity.
        if (looks_like_number(tokens_.peek().text)) l.color = color(e);
        scene_.lights.push_back(l);
    }

    void background(const NffToken& keyword) {
        if (background_) {
            throw tokens_.error_at(keyword, "a second background colour; a file has one",
                                   {line_note("the first", *background_)});
        }
        background_ = keyword;
        scene_.background = color({"background", keyword});
    }

    void view(const NffToken& keyword) {
        if (scene_.view) {
            throw tokens_.error_at(
                keyword, "a second view; a file has one",
                {"the first view is at line " + std::to_string(scene_.view->location.line)});
        }
        scene_.view = read_nff_view(tokens_, keyword, max_pixels_);
    }

    [[noreturn]] void unknown_entity(const NffToken& keyword) const {
        const std::string_view k = keyword.text;
        if (looks_like_number(k)) {
            std::vector<std::string> notes;
            if (!previous_.at_end()) {
                notes.push_back("numbers belong to the entity before them: the \"" +
                                std::string(previous_.text) + "\" at line " +
                                std::to_string(previous_.line) +
                                " may have more numbers than it takes");
            }
            notes.push_back(kEntityList);
            throw tokens_.error_at(keyword,
                                   "expected an entity keyword, got the number " + quote(k),
                                   std::move(notes));
        }
        if (std::find(kNffViewLines.begin(), kNffViewLines.end(), k) != kNffViewLines.end()) {
            throw tokens_.error_at(keyword, quote(k) + " is a line of a view, outside one",
                                   {kNffViewOrder});
        }
        std::vector<std::string> notes;
        for (const LongName& alias : kLongNames) {
            if (alias.name.size() == k.size() && edit_distance(alias.name, k) == 0) {
                notes.push_back("NFF writes a " + std::string(alias.name) + " as \"" +
                                std::string(alias.keyword) + "\"");
            }
        }
        notes.push_back(kEntityList + did_you_mean(k, kEntities));
        throw tokens_.error_at(keyword, "unknown NFF entity " + quote(k), std::move(notes));
    }

    NffTokenizer tokens_;
    std::int64_t max_pixels_;
    bool inherits_material_;
    NffScene scene_;
    NffToken previous_;                    // the last entity's keyword
    std::optional<NffToken> background_;   // the `b` keyword, once seen
    std::vector<NffToken> vertex_tokens_;  // where each vertex of the current polygon starts
};

// Where a piece may start: the beginning of a line whose first token is the keyword of an object
// or a material. All their values are numbers, so in a valid file such a token starts an entity.
bool starts_piece(std::string_view text, std::size_t line_start) {
    for (const std::string_view k : {"s ", "p ", "pp ", "c ", "f ", "s\t", "p\t", "c\t", "f\t"}) {
        if (text.substr(line_start, k.size()) == k) return true;
    }
    return false;
}

// Piece boundaries near every piece_bytes, each at a piece start (or the end of the text).
std::vector<std::size_t> piece_starts(std::string_view text, std::size_t piece_bytes) {
    std::vector<std::size_t> starts{0};
    for (std::size_t at = piece_bytes; at < text.size(); at += piece_bytes) {
        std::size_t newline = text.find('\n', std::max(at, starts.back() + 1) - 1);
        while (newline != std::string_view::npos && !starts_piece(text, newline + 1))
            newline = text.find('\n', newline + 1);
        if (newline == std::string_view::npos) break;
        starts.push_back(newline + 1);
        at = newline + 1;
    }
    return starts;
}

void shift(NffLocation& location, std::uint32_t lines) { location.line += lines; }

// Parses the text in pieces on all threads and joins them: the same NffScene as one parser gives,
// for a valid file. Anything a piece cannot settle alone (an error, an object before any
// material, a second view or background) returns nullopt, and the one parser reads the whole
// file to say what is wrong where.
std::optional<NffScene> parse_in_pieces(std::string_view text, const std::string& file_name,
                                        std::size_t piece_bytes, std::int64_t max_pixels) {
    const std::vector<std::size_t> starts = piece_starts(text, piece_bytes);
    const std::size_t n = starts.size();
    if (n < 2) return std::nullopt;
    std::vector<NffScene> pieces(n);
    std::vector<std::uint32_t> newlines(n);
    std::atomic<bool> failed = false;
    tbb::parallel_for(std::size_t(0), n, [&](std::size_t k) {
        const std::size_t end = k + 1 < n ? starts[k + 1] : text.size();
        const std::string_view piece = text.substr(starts[k], end - starts[k]);
        try {
            pieces[k] = NffParser(piece, file_name, max_pixels, k > 0).parse();
        } catch (const SceneError&) {
            failed = true;
        } catch (const std::bad_alloc&) {
            failed = true;
        }
        newlines[k] = std::uint32_t(std::count(piece.begin(), piece.end(), '\n'));
    });
    if (failed) return std::nullopt;

    NffScene scene;
    scene.file_name = file_name;
    std::uint32_t line_offset = 0;
    std::size_t objects = 0, materials = 0;
    for (const NffScene& piece : pieces) materials += piece.materials.size();
    scene.materials.reserve(materials);
    for (std::size_t k = 0; k < n; ++k) {
        NffScene& piece = pieces[k];
        if ((piece.view && scene.view) || (piece.background && scene.background))
            return std::nullopt;
        if (piece.view) {
            scene.view = piece.view;
            shift(scene.view->location, line_offset);
        }
        if (piece.background) scene.background = piece.background;
        for (NffLight& l : piece.lights) {
            shift(l.location, line_offset);
            scene.lights.push_back(l);
        }
        // The piece's own materials follow those of the pieces before it.
        const auto first_material = std::uint32_t(scene.materials.size());
        for (NffObject& o : piece.objects) {
            if (o.material == kInheritedMaterial) {
                if (first_material == 0) return std::nullopt;
                o.material = first_material - 1;
            } else {
                o.material += first_material;
            }
            shift(o.location, line_offset);
        }
        for (NffMaterial& m : piece.materials) {
            shift(m.location, line_offset);
            scene.materials.push_back(m);
        }
        objects += piece.objects.size();
        line_offset += newlines[k];
    }
    scene.objects.resize(objects);
    std::vector<std::size_t> first_object(n, 0);
    for (std::size_t k = 1; k < n; ++k)
        first_object[k] = first_object[k - 1] + pieces[k - 1].objects.size();
    tbb::parallel_for(std::size_t(0), n, [&](std::size_t k) {
        std::move(pieces[k].objects.begin(), pieces[k].objects.end(),
                  scene.objects.begin() + std::ptrdiff_t(first_object[k]));
        pieces[k].objects = {};
    });
    return scene;
}

}  // namespace

NffScene parse_nff(std::string_view text, const std::string& file_name, std::size_t piece_bytes,
                   std::int64_t max_pixels) {
    try {
        if (text.size() > piece_bytes) {
            if (auto scene = parse_in_pieces(text, file_name, piece_bytes, max_pixels))
                return std::move(*scene);
        }
        return NffParser(text, file_name, max_pixels).parse();
    } catch (const SceneError&) {
        throw;
    } catch (const std::bad_alloc&) {
        throw SceneError({file_name, 0, 0}, "out of memory while reading the scene");
    }
}

NffScene load_nff(const std::filesystem::path& file, std::uint64_t max_bytes,
                  std::int64_t max_pixels) {
    const std::string text = read_maybe_gzipped(file, max_bytes);
    return parse_nff(text, file.string(), kNffPieceBytes, max_pixels);
}

const NffView& require_view(const NffScene& scene) {
    if (!scene.view) {
        throw SceneError({scene.file_name, 0, 0},
                         "the file has no view: NFF needs a \"v\" entity to place the camera",
                         {kNffViewOrder});
    }
    return *scene.view;
}

}  // namespace glint
