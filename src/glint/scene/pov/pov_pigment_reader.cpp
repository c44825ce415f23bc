// POV-Ray's pigments: a colour, or a pattern with its colour map, wave, frequency, phase and
// turbulence, read onto glint's patterns (shading/pattern.h).
#include <algorithm>
#include <cmath>
#include <optional>
#include <string_view>

#include "glint/geometry/expression.h"
#include "glint/scene/pov/pov_item_reader.h"
#include "glint/shading/noise.h"

namespace glint {

namespace {

// POV-Ray's own bound on a colour map's entries.
constexpr std::size_t kMaxColorMapEntries = 256;

std::optional<PatternKind> pattern_kind(std::string_view w) {
    struct Named {
        std::string_view name;
        PatternKind kind;
    };
    static constexpr Named kKinds[] = {
        {"agate", PatternKind::agate},
        {"bozo", PatternKind::bozo},
        {"boxed", PatternKind::boxed},
        {"brick", PatternKind::brick},
        {"checker", PatternKind::checker},
        {"hexagon", PatternKind::hexagon},
        {"crackle", PatternKind::crackle},
        {"cylindrical", PatternKind::cylindrical},
        {"function", PatternKind::function},
        {"gradient", PatternKind::gradient},
        {"granite", PatternKind::granite},
        {"leopard", PatternKind::leopard},
        {"marble", PatternKind::marble},
        {"onion", PatternKind::onion},
        {"planar", PatternKind::planar},
        {"radial", PatternKind::radial},
        {"spherical", PatternKind::spherical},
        {"spotted", PatternKind::bozo},  // the same function in POV-Ray
        {"bumps", PatternKind::bozo},    // as a pigment, too
        {"wood", PatternKind::wood},
        {"mandel", PatternKind::mandel},
        {"ripples", PatternKind::ripples},
        {"waves", PatternKind::waves},
        {"spiral1", PatternKind::spiral1},
        {"spiral2", PatternKind::spiral2},
        {"wrinkles", PatternKind::wrinkles},
    };
    for (const Named& k : kKinds)
        if (k.name == w) return k.kind;
    return std::nullopt;
}

}  // namespace

bool PovItemReader::is_pigment_pattern(std::string_view name) {
    return pattern_kind(name).has_value();
}

namespace {

bool starts_color(const PovToken& t) {
    return t.is_word("color") || t.is_word("colour") || t.is_word("rgb") || t.is_word("rgbf") ||
           t.is_word("rgbt") || t.is_word("rgbft") || t.is_word("red") || t.is_word("green") ||
           t.is_word("blue") || t.is_word("srgb");
}

PovColorMap black_to_white() {
    PovColorMap map;
    map.stops = {{0, PovVector::of(0, 5)}, {1, PovVector::of(0, 5)}};
    for (int i = 0; i < 3; ++i) map.stops[1].color[i] = 1;
    return map;
}

}  // namespace

PovColorMap PovItemReader::blend_map(const PovToken& keyword, std::string_view entry_kind,
                                     const std::function<void(double, PovColorMap&)>& entry) {
    parser_.expect("{", "after " + keyword.text);
    PovColorMap map;
    if (auto d = take_declared<PovColorMap>()) {
        map = *d;
    }
    for (PovToken t = parser_.next(); !t.is_symbol("}"); t = parser_.next()) {
        if (!t.is_symbol("["))
            throw parser_.error_at(
                t, "expected '[' or '}' in " + keyword.text + ", got " + describe(t));
        if (map.stops.size() + 2 > kMaxColorMapEntries)
            throw parser_.error_at(t, keyword.text + " has more than " +
                                          std::to_string(kMaxColorMapEntries) + " entries");
        const double at = parser_.finite_float("as the entry's value");
        parser_.accept(",");
        entry(at, map);
    }
    if (map.stops.empty())
        throw parser_.error_at(
            keyword, keyword.text + " needs at least one [value " + std::string(entry_kind) + "]");
    // POV-Ray looks entries up in their order; written out of order, they are taken sorted.
    std::stable_sort(map.stops.begin(), map.stops.end(),
                     [](const PovColorStop& x, const PovColorStop& y) { return x.at < y.at; });
    return map;
}

PovColorMap PovItemReader::color_map(const PovToken& keyword) {
    return blend_map(keyword, "colour", [&](double a, PovColorMap& map) {
        const PovToken& next = parser_.peek();
        const PovValue* declared_value =
            next.kind == PovTokenKind::identifier ? parser_.symbols().find(next.text) : nullptr;
        if (next.kind == PovTokenKind::number ||
            (declared_value && std::holds_alternative<double>(*declared_value))) {
            // [a b color C1 color C2]: POV-Ray's old form, C1 at a and C2 at b.
            const double b = parser_.finite_float("as the entry's end");
            parser_.accept(",");
            const PovVector c1 = parser_.color_expression("as the entry's first colour");
            parser_.accept(",");
            const PovVector c2 = parser_.color_expression("as the entry's second colour");
            map.stops.push_back({a, c1, nullptr});
            map.stops.push_back({b, c2, nullptr});
        } else {
            map.stops.push_back({a, parser_.color_expression("as the entry's colour"), nullptr});
        }
        parser_.expect("]", "after the entry's colour");
    });
}

PovPigment PovItemReader::pattern(const PovToken& name) {
    PovPigment p;
    p.kind = PovPigment::Kind::pattern;
    p.spec.kind = *pattern_kind(name.text);
    p.spec.wave = default_wave(p.spec.kind);
    p.map = black_to_white();
    if (p.spec.kind == PatternKind::gradient) {
        const PovToken at = parser_.peek();
        const Vector3 d = to_vector(parser_.finite_vector("after gradient"));
        if (!(length(d) > 0)) throw parser_.error_at(at, "gradient direction must not be zero");
        p.spec.direction = normalize(d);
    } else if (p.spec.kind == PatternKind::function) {
        // function { f(x, y, z) } onto glint's expressions, as an isosurface's.
        parser_.expect("{", "after function");
        std::string uses;
        const std::string text =
            call_text(PovFunction{3, function_body({}, uses), {}, {}}, {"x", "y", "z"});
        parser_.expect("}", "to close the function");
        if (!uses.empty()) {
            PovPigment unread;
            unread.kind = PovPigment::Kind::unsupported;
            unread.pattern = name.text;
            unread.uses = uses;
            unread.at = name.at;
            return unread;
        }
        auto compiled = compile_expression(text, {});
        if (auto* error = std::get_if<ExpressionError>(&compiled))
            throw parser_.error_at(name, "function pattern: " + error->message);
        p.spec.function =
            std::make_shared<const Expression>(std::move(std::get<Expression>(compiled)));
    } else if (p.spec.kind == PatternKind::mandel) {
        p.spec.iterations = parser_.whole_number("as mandel's iterations", 1, 1 << 16);
    } else if (p.spec.kind == PatternKind::spiral1 || p.spec.kind == PatternKind::spiral2) {
        // A whole number of arms, as POV-Ray truncates it.
        p.spec.arms = std::trunc(float(parser_.finite_float("as the spiral's arms")));
    } else if (is_list_pattern(p.spec.kind)) {
        // The colours each value picks, POV-Ray's defaults unless the pattern lists its own:
        // checker blue and green; hexagon blue, green and red; brick's mortar grey, its bricks
        // brick red.
        const auto rgb = [](double r, double g, double b) {
            PovVector c = PovVector::of(0, 5);
            c[0] = r, c[1] = g, c[2] = b;
            return c;
        };
        std::vector<PovVector> colors = p.spec.kind == PatternKind::checker
                                            ? std::vector{rgb(0, 0, 1), rgb(0, 1, 0)}
                                        : p.spec.kind == PatternKind::hexagon
                                            ? std::vector{rgb(0, 0, 1), rgb(0, 1, 0), rgb(1, 0, 0)}
                                            : std::vector{rgb(0.5, 0.5, 0.5), rgb(0.6, 0.15, 0.15)};
        const auto colour_next = [&] {
            const PovToken& ahead = parser_.peek_item();
            return starts_color(ahead) || ahead.is_symbol("<") ||
                   (ahead.kind == PovTokenKind::identifier && parser_.symbols().find(ahead.text) &&
                    !declared<PovColorMap>(ahead));
        };
        p.map.stops.clear();
        for (std::size_t i = 0; i < colors.size(); ++i)
            p.map.stops.push_back({float(i) / float(colors.size() - 1), colors[i], nullptr});
        // The colours or pigments given, in order; the ones not given stay.
        for (PovColorStop& stop : p.map.stops) {
            if (&stop != &p.map.stops.front()) parser_.accept(",");
            if (parser_.peek_item().is_word("pigment")) {
                parser_.next();
                stop.pigment = std::make_shared<const PovPigment>(pigment({}));
            } else if (colour_next()) {
                stop.color = parser_.color_expression("as the " + name.text + "'s colour");
            } else {
                break;
            }
        }
    }
    return p;
}

bool PovItemReader::pattern_modifier(const PovToken& token, PovPigment& p) {
    const std::string& w = token.text;
    PatternSpec& s = p.spec;
    if (w == "color_map" || w == "colour_map") {
        p.map = color_map(token);
    } else if (w == "pigment_map" || w == "density_map") {
        p.map = pigment_map(token);
    } else if (w == "turbulence") {
        s.turbulence = to_vector(parser_.finite_vector("after turbulence"));
    } else if (w == "octaves") {
        s.octaves = parser_.whole_number("after octaves", 1, kMaxOctaves);
    } else if (w == "omega" || w == "lambda") {
        (w == "omega" ? s.omega : s.lambda) = float(parser_.finite_float("after " + w));
    } else if (w == "brick_size") {
        const PovToken at = parser_.peek();
        s.brick_size = to_vector(parser_.finite_vector("after brick_size"));
        if (!(s.brick_size.x > 0 && s.brick_size.y > 0 && s.brick_size.z > 0))
            throw parser_.error_at(at, "brick_size must be > 0 on every axis");
    } else if (w == "mortar") {
        const PovToken at = parser_.peek();
        s.mortar = float(parser_.finite_float("after mortar"));
        if (!(s.mortar >= 0)) throw parser_.error_at(at, "mortar must be >= 0");
    } else if (w == "frequency" || w == "phase") {
        (w == "frequency" ? s.frequency : s.phase) = float(parser_.finite_float("after " + w));
    } else if (w == "ramp_wave") {
        s.wave = PatternWave::ramp;
    } else if (w == "triangle_wave") {
        s.wave = PatternWave::triangle;
    } else if (w == "sine_wave") {
        s.wave = PatternWave::sine;
    } else if (w == "scallop_wave") {
        s.wave = PatternWave::scallop;
    } else if (w == "cubic_wave") {
        s.wave = PatternWave::cubic;
    } else if (w == "poly_wave") {
        s.wave = PatternWave::poly;
        s.exponent = float(optional_amount());
    } else if (w == "agate_turb" || w == "metric" || w == "offset") {
        parser_.finite_float("after " + w);
    } else if (w == "form") {
        parser_.finite_vector("after form");
    } else if (w == "solid") {
    } else if (w == "noise_generator") {
        parser_.whole_number("after noise_generator", 1, 3);
    } else if (w == "quick_color" || w == "quick_colour") {
        parser_.color_expression("after " + w);
    } else {
        return false;
    }
    if ((w == "form" || w == "metric" || w == "offset" || w == "solid") && !warned_crackle_) {
        warnings_.push_back(
            "crackle's form, metric, offset and solid are read, not used: "
            "glint's crackle is the distance to the second nearest point less "
            "the nearest's");
        warned_crackle_ = true;
    }
    return true;
}

PovColorMap PovItemReader::pigment_map(const PovToken& keyword) {
    return blend_map(keyword, "pigment", [&](double at, PovColorMap& map) {
        auto pigment = std::make_shared<const PovPigment>(pigment_body({}, "]"));
        const PovVector color = pigment->color;
        map.stops.push_back({at, color, std::move(pigment)});
    });
}

bool PovItemReader::warp(const PovToken& keyword, PovPigment& p) {
    parser_.expect("{", "after warp");
    const PovToken kind = parser_.next();
    PatternSpec& s = p.spec;
    // One turbulence a pattern: its own or a warp's.
    if (!kind.is_word("turbulence") || s.warped || s.turbulence != Vector3{}) {
        if (!kind.is_symbol("}")) parser_.skip_to_closing_brace(keyword);
        return false;
    }
    s.turbulence = to_vector(parser_.finite_vector("after turbulence"));
    s.octaves = 6, s.omega = 0.5f, s.lambda = 2;
    for (PovToken t = parser_.next(); !t.is_symbol("}"); t = parser_.next()) {
        if (t.is_word("octaves"))
            s.octaves = parser_.whole_number("after octaves", 1, kMaxOctaves);
        else if (t.is_word("omega") || t.is_word("lambda"))
            (t.text == "omega" ? s.omega : s.lambda) =
                float(parser_.finite_float("after " + t.text));
        else
            throw parser_.error_at(
                t, "expected octaves, omega, lambda or '}' in warp { turbulence }, got " +
                       describe(t));
    }
    // The transforms so far lie beyond the turbulence: the point it moves goes through them.
    s.warped = true;
    s.after_turbulence = p.transform.inverse();
    p.transform = Transform{};
    return true;
}

PovPigment PovItemReader::pigment(const PovPigment& base) {
    parser_.expect("{", "after pigment");
    return pigment_body(base, "}");
}

PovPigment PovItemReader::pigment_body(const PovPigment& base, std::string_view closing) {
    // Past a pigment glint does not read yet, to its end.
    const auto skip_rest = [&](const PovToken& from) {
        if (closing == "}") return parser_.skip_to_closing_brace(from);
        for (int depth = 0;;) {
            const PovToken t = parser_.next();
            if (t.kind == PovTokenKind::end)
                throw parser_.error_at(from, "a map entry is not closed by ]");
            if (depth == 0 && t.is_symbol("]")) return;
            depth += t.is_symbol("{") || t.is_symbol("[")   ? 1
                     : t.is_symbol("}") || t.is_symbol("]") ? -1
                                                            : 0;
        }
    };
    PovPigment p = base;
    std::optional<PovToken> average;
    // uv_mapping: the pattern on the surface's uv, written first or among the modifiers.
    std::optional<PovPosition> uv_mapping;
    if (parser_.peek_item().is_word("uv_mapping")) uv_mapping = parser_.next().at;
    if (auto d = take_declared<PovPigment>()) {
        p = *d;
    } else if (parser_.peek_item().is_word("image_map")) {
        p = image_map(parser_.next());
    } else if (const PovToken& first = parser_.peek_item();
               first.kind == PovTokenKind::identifier && pattern_kind(first.text)) {
        p = pattern(parser_.next());
    } else if (first.is_word("average")) {
        average = parser_.next();
        p = PovPigment{};
        p.kind = PovPigment::Kind::pattern;
        p.average = true;
    } else if (first.kind == PovTokenKind::identifier && !starts_color(first) &&
               !parser_.symbols().find(first.text)) {
        // A pattern glint does not read yet: only an object that uses it stops the scene.
        const PovToken pattern = parser_.next();
        p = PovPigment{};
        p.kind = PovPigment::Kind::unsupported;
        p.pattern = pattern.text;
        p.at = pattern.at;
        skip_rest(pattern);
        return p;
    } else if (!first.is_symbol(closing)) {
        p.kind = PovPigment::Kind::color;
        p.color = parser_.color_expression("as the pigment's colour");
    }
    for (;;) {
        const PovToken token = parser_.next();
        if (token.is_symbol(closing)) break;
        if (token.kind == PovTokenKind::end || (closing == "]" && token.is_symbol("}")))
            throw parser_.error_at(token, "expected '" + std::string(closing) +
                                              "' after the pigment, got " + describe(token));
        if (const auto step = transform_step(token)) {
            p.transform = *step * p.transform;
            continue;
        }
        if (token.is_word("uv_mapping")) {
            uv_mapping = token.at;
            continue;
        }
        if (token.kind == PovTokenKind::identifier && pattern_modifier(token, p)) continue;
        if (token.is_word("warp") && p.kind == PovPigment::Kind::pattern && warp(token, p))
            continue;
        // Another modifier (another warp, ...): the pigment is one glint does not read yet, an
        // error only where an object uses it.
        PovPigment unread;
        unread.kind = PovPigment::Kind::unsupported;
        unread.pattern = token.text;
        unread.at = token.at;
        skip_rest(token);
        return unread;
    }
    if (average && !std::any_of(p.map.stops.begin(), p.map.stops.end(),
                                [](const PovColorStop& s) { return s.pigment != nullptr; }))
        throw parser_.error_at(*average, "average needs a pigment_map");
    if (uv_mapping && (p.kind == PovPigment::Kind::image || p.kind == PovPigment::Kind::pattern))
        p.uv_mapping = true;
    return p;
}

}  // namespace glint
