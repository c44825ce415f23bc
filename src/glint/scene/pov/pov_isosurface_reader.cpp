// POV-Ray's isosurface { } onto glint's implicit surfaces: the points of its container where
// the function equals the threshold, inside where it is below. Closed, the container's own
// surface shows where it cuts the inside (an intersection with it); `open`, only the function's
// surface (clipped by it).
#include <memory>

#include "glint/geometry/implicit_surface.h"
#include "glint/scene/pov/pov_item_reader.h"
#include "glint/scene/pov/pov_polynomial.h"

namespace glint {

Shape PovItemReader::isosurface(const PovToken& keyword) {
    std::optional<std::string> f;
    std::string unsupported;
    PovToken function_at = keyword;
    double threshold = 0;
    bool open = false;
    Shape container = Box{{-1, -1, -1}, {1, 1, 1}};  // POV-Ray's default
    for (;;) {
        const PovToken& ahead = parser_.peek_item();
        if (ahead.is_word("function")) {
            function_at = parser_.next();
            parser_.expect("{", "after function");
            f = call_text(PovFunction{3, function_body({}, unsupported), {}, {}}, {"x", "y", "z"});
            parser_.expect("}", "to close the function");
        } else if (ahead.is_word("threshold")) {
            parser_.next();
            threshold = parser_.finite_float("after threshold");
        } else if (ahead.is_word("contained_by")) {
            parser_.next();
            parser_.expect("{", "after contained_by");
            const PovToken kind = parser_.next();
            parser_.expect("{", "after " + describe(kind));
            if (kind.is_word("box")) {
                const PovVector a = point("as the box's corner");
                parser_.accept(",");
                const PovVector b = point("as the box's other corner");
                const Box box{min(to_point(a), to_point(b)), max(to_point(a), to_point(b))};
                if (!(box.min.x < box.max.x && box.min.y < box.max.y && box.min.z < box.max.z))
                    throw parser_.error_at(kind, "contained_by's box must have volume");
                container = box;
            } else if (kind.is_word("sphere")) {
                const PovVector c = point("as the sphere's centre");
                parser_.accept(",");
                const float radius = number("as the sphere's radius");
                if (!(radius > 0)) throw parser_.error_at(kind, "sphere radius must be > 0");
                container = Sphere{to_point(c), radius};
            } else {
                throw parser_.error_at(
                    kind, "contained_by holds a box or a sphere, got " + describe(kind));
            }
            parser_.expect("}", "to close the " + kind.text);
            parser_.expect("}", "to close contained_by");
        } else if (ahead.is_word("open")) {
            parser_.next();
            open = true;
        } else if (ahead.is_word("accuracy") || ahead.is_word("max_gradient") ||
                   ahead.is_word("max_trace")) {
            // POV-Ray's search settings: glint's interval search needs none.
            const PovToken setting = parser_.next();
            parser_.finite_float("after " + setting.text);
        } else if (ahead.is_word("evaluate")) {
            parser_.next();
            for (int i = 0; i < 3; ++i) {
                if (i > 0) parser_.accept(",");
                parser_.finite_float("after evaluate");
            }
        } else if (ahead.is_word("all_intersections")) {
            parser_.next();
        } else {
            break;
        }
    }
    if (!f) throw parser_.error_at(keyword, "an isosurface needs a function { }");
    if (!unsupported.empty())
        throw parser_.error_at(
            function_at,
            "the isosurface's function uses " + unsupported + ", which glint does not compute yet",
            {"docs/povray.md lists what glint reads"});
    auto compiled = compile_expression(*f + "-" + expression_number(threshold), {});
    if (auto* error = std::get_if<ExpressionError>(&compiled))
        throw parser_.error_at(function_at, "isosurface: " + error->message);
    ImplicitSurface surface;
    surface.f = std::make_shared<const Expression>(std::move(std::get<Expression>(compiled)));
    const Bounds3 box = bounds(container);
    surface.region = open ? box : loosened(box);
    surface.tolerance = 1e-4f * max_component(box.diagonal());
    if (open)
        return std::holds_alternative<Box>(container)
                   ? Shape{surface}
                   : csg_of(surface, container, CsgOperation::clip);
    return csg_of(surface, container, CsgOperation::intersection);
}

}  // namespace glint
