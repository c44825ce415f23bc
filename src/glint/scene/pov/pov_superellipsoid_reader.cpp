// POV-Ray's superellipsoid { <e, n> } onto glint's implicit surfaces: Barr's superquadric
// (|x|^(2/e) + |y|^(2/e))^(e/n) + |z|^(2/n) = 1 inside the cube from -1 to 1, a solid.
#include "glint/geometry/implicit_surface.h"
#include "glint/scene/pov/pov_item_reader.h"
#include "glint/scene/pov/pov_polynomial.h"

namespace glint {

Shape PovItemReader::superellipsoid(const PovToken& keyword) {
    const PovToken at = parser_.peek();
    const PovVector en = parser_.finite_vector("as the superellipsoid's <e, n>", 2);
    const double e = en[0], n = en[1];
    // Beyond these the exponents reach thousands and the surface is a box to within rounding.
    if (!(e >= 1e-3 && e <= 1e3 && n >= 1e-3 && n <= 1e3))
        throw parser_.error_at(at, "superellipsoid's e and n must be in [0.001, 1000]");
    const std::string source = "(abs(x)^" + expression_number(2 / e) + " + abs(y)^" +
                               expression_number(2 / e) + ")^" + expression_number(e / n) +
                               " + abs(z)^" + expression_number(2 / n) + " - 1";
    auto compiled = compile_expression(source, {});
    if (auto* error = std::get_if<ExpressionError>(&compiled))
        throw parser_.error_at(keyword, "superellipsoid: " + error->message);
    ImplicitSurface surface;
    surface.f = std::make_shared<const Expression>(std::move(std::get<Expression>(compiled)));
    surface.region = loosened(Bounds3{{-1, -1, -1}, {1, 1, 1}});
    return surface;
}

}  // namespace glint
