// Reads POV-Ray's prism onto glint's prism: the outlines of its spline, swept along y; its text
// as a union of prisms, a letter each: the glyph's outlines swept along z; and its lathe: the
// spline's curve turned round y.
#include "glint/geometry/spline_outlines.h"
#include "glint/scene/font_outlines.h"
#include "glint/scene/pov/pov_item_reader.h"

namespace glint {

std::optional<SplineKind> PovItemReader::spline_keyword() {
    const PovToken& t = parser_.peek_item();
    if (!(t.is_word("linear_spline") || t.is_word("quadratic_spline") ||
          t.is_word("cubic_spline") || t.is_word("bezier_spline")))
        return std::nullopt;
    const std::string word = parser_.next().text;
    return spline_kind(word.substr(0, word.find('_')));
}

std::vector<Point2> PovItemReader::point_list(const std::string& shape, int least) {
    const int count =
        parser_.whole_number("as the " + shape + "'s number of points", least, 1'000'000);
    std::vector<Point2> points;
    for (int i = 0; i < count; ++i) {
        parser_.accept(",");
        const PovVector p = parser_.finite_vector("as a " + shape + " point", 2);
        points.push_back({float(p[0]), float(p[1])});
    }
    return points;
}

bool PovItemReader::open_and_sturm() {
    // They belong to the shape: they come before the modifiers. sturm, POV-Ray's choice of root
    // solver, means nothing to glint.
    bool open = false;
    for (;;) {
        if (parser_.peek_item().is_word("open")) {
            parser_.next();
            open = true;
        } else if (parser_.peek_item().is_word("sturm")) {
            parser_.next();
        } else {
            return open;
        }
    }
}

Shape PovItemReader::prism(const PovToken& keyword) {
    SplineKind kind = SplineKind::linear;
    for (;;) {
        if (const auto spline = spline_keyword()) {
            kind = *spline;
        } else if (parser_.peek_item().is_word("linear_sweep")) {
            parser_.next();
        } else if (parser_.peek_item().is_word("conic_sweep")) {
            throw unsupported(parser_.next(), "in a prism");
        } else {
            break;
        }
    }
    const float h1 = float(parser_.finite_float("as the prism's first height"));
    parser_.accept(",");
    const float h2 = float(parser_.finite_float("as the prism's second height"));
    parser_.accept(",");
    const std::vector<Point2> points = point_list("prism", 3);
    const bool open = open_and_sturm();
    auto outlines = spline_outlines(kind, points);
    if (const auto* problem = std::get_if<std::string>(&outlines))
        throw parser_.error_at(keyword, "prism: " + *problem);
    if (std::get<SplineOutlines>(outlines).closed_by_line > 0)
        warnings_.push_back(
            "prism: an outline that does not end on its first point is closed by "
            "a straight edge");
    auto made = make_prism(std::get<SplineOutlines>(outlines).outlines, std::min(h1, h2),
                           std::max(h1, h2), open);
    if (const auto* problem = std::get_if<std::string>(&made))
        throw parser_.error_at(keyword, *problem);
    return std::get<Prism>(std::move(made));
}

// A lathe of the curve, or the error at the keyword.
Shape PovItemReader::lathe_of(const PovToken& keyword, std::variant<Outline, std::string> curve) {
    if (const auto* problem = std::get_if<std::string>(&curve))
        throw parser_.error_at(keyword, keyword.text + ": " + *problem);
    auto made = make_lathe(std::get<Outline>(curve));
    if (const auto* problem = std::get_if<std::string>(&made))
        throw parser_.error_at(keyword, *problem);
    return std::get<Lathe>(std::move(made));
}

Shape PovItemReader::lathe(const PovToken& keyword) {
    const SplineKind kind = spline_keyword().value_or(SplineKind::linear);
    const std::vector<Point2> points = point_list("lathe", 2);
    open_and_sturm();
    return lathe_of(keyword, spline_curve(kind, points));
}

Shape PovItemReader::sor(const PovToken& keyword) {
    const std::vector<Point2> points = point_list("sor", 4);
    const bool open = open_and_sturm();
    return lathe_of(keyword, sor_curve(points, open));
}

void PovItemReader::text(const PovToken& keyword, PovObject& object) {
    const PovToken kind = parser_.next();
    if (!kind.is_word("ttf")) throw unsupported(kind, "in text");
    const PovToken font_token = parser_.peek();
    std::string font = parser_.string_expression("as the text's font file");
    parser_.accept(",");
    const std::string letters = parser_.string_expression("as the text's string");
    parser_.accept(",");
    const PovToken thickness_token = parser_.peek();
    const double thickness = parser_.finite_float("as the text's thickness");
    if (thickness == 0) throw parser_.error_at(thickness_token, "text thickness must not be 0");
    parser_.accept(",");
    const PovVector offset = parser_.finite_vector("as the text's offset");
    // POV-Ray looks for a font named without an extension as a .ttf file.
    if (std::filesystem::path(font).extension().empty()) font += ".ttf";
    const auto [path, bytes] = parser_.read_file(keyword, font_token, font, "font");
    auto laid_out = text_outlines(bytes, font, letters, to_vector(offset));
    if (const auto* problem = std::get_if<std::string>(&laid_out))
        throw parser_.error_at(font_token, *problem);
    const TextOutlines& text = std::get<TextOutlines>(laid_out);
    if (!text.missing.empty()) {
        std::string list;
        for (const std::string& c : text.missing) list += (list.empty() ? "" : " ") + c;
        warnings_.push_back("text: " + font + " has no glyph for " + list +
                            "; its missing-glyph shape stands in");
    }
    // A prism sweeps along y in its own space: a letter's (x, y) is written as (x, -y) there,
    // and a quarter turn about x stands it up, swept from z = 0 to the thickness.
    const Transform upright = Transform::rotate({1, 0, 0}, 90);
    object.csg = PovObject::Csg::group;
    for (const std::vector<Outline>& glyph : text.glyphs) {
        std::vector<Outline> flipped = glyph;
        for (Outline& outline : flipped) {
            for (OutlineEdge& e : outline) {
                for (Point2* p : {&e.a, &e.b, &e.tangent_a, &e.tangent_b}) p->y = -p->y;
            }
        }
        auto made =
            make_prism(flipped, float(std::min(thickness, 0.0)), float(std::max(thickness, 0.0)));
        if (const auto* problem = std::get_if<std::string>(&made))
            throw parser_.error_at(keyword, "text: " + *problem);
        PovObject letter;
        letter.shape = std::get<Prism>(std::move(made));
        letter.transform = upright;
        letter.at = keyword.at;
        object.children.push_back(std::make_shared<const PovObject>(std::move(letter)));
    }
    if (object.children.empty())
        warnings_.push_back("text: \"" + letters + "\" has no letter with an outline to draw");
}

}  // namespace glint
