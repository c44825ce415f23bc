// The terms of POV-Ray's polynomials in its order, as text for glint's expression compiler.
#include "glint/scene/pov/pov_polynomial.h"

#include <charconv>
#include <utility>

namespace glint {

std::string expression_number(double v) {
    char text[32];
    const auto end = std::to_chars(text, text + sizeof text, v).ptr;  // shortest exact form
    return "(" + std::string(text, end) + ")";
}

int polynomial_term_count(int order) { return (order + 1) * (order + 2) * (order + 3) / 6; }

TermPowers polynomial_term(int order, int i) {
    int index = 0;
    for (int x = order; x >= 0; --x)
        for (int y = order - x; y >= 0; --y)
            for (int z = order - x - y; z >= 0; --z)
                if (index++ == i) return {x, y, z};
    return {};
}

std::string polynomial_text(int order, const std::vector<double>& coefficients) {
    std::string text;
    for (int i = 0; i < int(coefficients.size()); ++i) {
        if (coefficients[std::size_t(i)] == 0) continue;
        if (!text.empty()) text += " + ";
        text += expression_number(coefficients[std::size_t(i)]);
        const TermPowers p = polynomial_term(order, i);
        const std::pair<const char*, int> powers[] = {{"x", p.x}, {"y", p.y}, {"z", p.z}};
        for (const auto& [name, power] : powers) {
            if (power == 0) continue;
            text += std::string("*") + name;
            if (power > 1) text += "^" + std::to_string(power);
        }
    }
    return text.empty() ? "0" : text;
}

}  // namespace glint
