// POV-Ray's polynomial surfaces (cubic, quartic, poly) as glint's implicit surfaces: the
// polynomial's terms come in POV-Ray's order, by falling powers of x, then of y, then of z
// (quartic: x^4, x^3 y, x^3 z, x^3, x^2 y^2, ..., z, 1), and its inside is where it is < 0.
#pragma once

#include <string>
#include <vector>

namespace glint {

// The number as expression text that reads back exactly, in parentheses: "(-0.25)".
std::string expression_number(double v);

// The number of terms of a polynomial of this order in x, y and z: (n+1)(n+2)(n+3)/6.
int polynomial_term_count(int order);

// The powers of x, y and z of term i (from 0) of a polynomial of this order.
struct TermPowers {
    int x = 0, y = 0, z = 0;
};
TermPowers polynomial_term(int order, int i);

// The polynomial as glint's expression text ("2*x^2*y + -1"), its zero terms left out; "0" when
// all are. coefficients.size() == polynomial_term_count(order).
std::string polynomial_text(int order, const std::vector<double>& coefficients);

}  // namespace glint
