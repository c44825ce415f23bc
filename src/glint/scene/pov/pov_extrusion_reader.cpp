// Reads POV-Ray's prism onto glint's prism: the outlines of its spline, swept along y.
#include "glint/geometry/spline_outlines.h"
#include "glint/scene/pov/pov_item_reader.h"

namespace glint {

Shape PovItemReader::prism(const PovToken& keyword) {
    SplineKind kind = SplineKind::linear;
    for (;;) {
        const PovToken& t = parser_.peek_item();
        if (t.is_word("linear_sweep")) {
            parser_.next();
        } else if (t.is_word("conic_sweep")) {
            throw unsupported(parser_.next(), "in a prism");
        } else if (t.is_word("linear_spline") || t.is_word("quadratic_spline") ||
                   t.is_word("cubic_spline") || t.is_word("bezier_spline")) {
            const std::string word = parser_.next().text;
            kind = *spline_kind(word.substr(0, word.find('_')));
        } else {
            break;
        }
    }
    const float h1 = float(parser_.finite_float("as the prism's first height"));
    parser_.accept(",");
    const float h2 = float(parser_.finite_float("as the prism's second height"));
    parser_.accept(",");
    const int count = parser_.whole_number("as the prism's number of points", 3, 1'000'000);
    std::vector<Point2> points;
    for (int i = 0; i < count; ++i) {
        parser_.accept(",");
        const PovVector p = parser_.finite_vector("as a prism point", 2);
        points.push_back({float(p[0]), float(p[1])});
    }
    // `open` and `sturm` belong to the shape: they come before the modifiers.
    bool open = false;
    for (;;) {
        if (parser_.peek_item().is_word("open")) {
            parser_.next();
            open = true;
        } else if (parser_.peek_item().is_word("sturm")) {
            parser_.next();
        } else {
            break;
        }
    }
    auto outlines = spline_outlines(kind, points);
    if (const auto* problem = std::get_if<std::string>(&outlines))
        throw parser_.error_at(keyword, "prism: " + *problem);
    if (std::get<SplineOutlines>(outlines).closed_by_line > 0)
        warnings_.push_back("prism: an outline that does not end on its first point is closed by "
                            "a straight edge");
    auto made = make_prism(std::get<SplineOutlines>(outlines).outlines, std::min(h1, h2),
                           std::max(h1, h2), open);
    if (const auto* problem = std::get_if<std::string>(&made))
        throw parser_.error_at(keyword, *problem);
    return std::get<Prism>(std::move(made));
}

}  // namespace glint
