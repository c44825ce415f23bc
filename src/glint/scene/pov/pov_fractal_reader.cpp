// Reads POV-Ray's julia_fractal onto glint's quaternion Julia set: the quaternion algebra with
// sqr, sliced by w = 0 (or POV-Ray's slice along the fourth axis).
#include "glint/scene/pov/pov_item_reader.h"

namespace glint {

Shape PovItemReader::julia_fractal(const PovToken& keyword) {
    const PovVector c = parser_.finite_vector("as the julia_fractal's constant", 4);
    JuliaSet julia;
    julia.c = {float(c[0]), float(c[1]), float(c[2]), float(c[3])};
    for (;;) {
        const PovToken& t = parser_.peek_item();
        if (t.is_word("quaternion") || t.is_word("sqr")) {
            parser_.next();  // glint's algebra and function
        } else if (t.is_word("max_iteration")) {
            parser_.next();
            julia.max_iterations = parser_.whole_number("after max_iteration", 1, 1000);
        } else if (t.is_word("precision")) {
            // POV-Ray steps 1 / precision along the ray, and the surface it finds is as thick:
            // glint's sphere tracing stops as near.
            const PovToken at = parser_.next();
            const double precision = parser_.finite_float("after precision");
            if (!(precision > 0)) throw parser_.error_at(at, "precision must be > 0");
            julia.epsilon = float(std::min(0.1, 1 / precision));
        } else if (t.is_word("slice")) {
            const PovToken slice = parser_.next();
            const PovVector normal = parser_.finite_vector("as the slice's normal", 4);
            parser_.accept(",");
            const double distance = parser_.finite_float("as the slice's distance");
            if (normal[0] != 0 || normal[1] != 0 || normal[2] != 0 || normal[3] == 0)
                throw parser_.error_at(slice,
                                       "julia_fractal slice is read along the fourth axis "
                                       "only (slice <0, 0, 0, 1>, w)",
                                       {"docs/povray.md lists what glint reads"});
            julia.slice_w = float(distance / normal[3]);
        } else if (t.is_word("hypercomplex") || t.is_word("cube") || t.is_word("exp") ||
                   t.is_word("reciprocal") || t.is_word("sin") || t.is_word("asin") ||
                   t.is_word("sinh") || t.is_word("asinh") || t.is_word("cos") ||
                   t.is_word("acos") || t.is_word("cosh") || t.is_word("acosh") ||
                   t.is_word("tan") || t.is_word("atan") || t.is_word("tanh") ||
                   t.is_word("atanh") || t.is_word("ln") || t.is_word("pwr")) {
            throw unsupported(parser_.next(), "in a julia_fractal");
        } else {
            break;
        }
    }
    if (const std::string problem = describe_problem(julia); !problem.empty())
        throw parser_.error_at(keyword, problem);
    return julia;
}

}  // namespace glint
