// POV-Ray's polynomial terms in its order, and their text for glint's expression compiler.
#include "glint/scene/pov/pov_polynomial.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "glint/geometry/expression.h"

namespace glint {
namespace {

TEST(PovPolynomial, TermsComeByFallingPowersOfXThenYThenZ) {
    EXPECT_EQ(polynomial_term_count(2), 10);
    EXPECT_EQ(polynomial_term_count(3), 20);
    EXPECT_EQ(polynomial_term_count(4), 35);
    // The quartic's terms as POV-Ray's documentation lists them: A1 x^4, A2 x^3 y, A5 x^2 y^2,
    // A10 x^2, A13 x y^2, A21 y^4, A26 y^2, A31 z^4, A35 the constant.
    const auto powers = [](int order, int i) {
        const TermPowers p = polynomial_term(order, i);
        return std::vector<int>{p.x, p.y, p.z};
    };
    EXPECT_EQ(powers(4, 0), (std::vector<int>{4, 0, 0}));
    EXPECT_EQ(powers(4, 1), (std::vector<int>{3, 1, 0}));
    EXPECT_EQ(powers(4, 4), (std::vector<int>{2, 2, 0}));
    EXPECT_EQ(powers(4, 9), (std::vector<int>{2, 0, 0}));
    EXPECT_EQ(powers(4, 12), (std::vector<int>{1, 2, 0}));
    EXPECT_EQ(powers(4, 20), (std::vector<int>{0, 4, 0}));
    EXPECT_EQ(powers(4, 25), (std::vector<int>{0, 2, 0}));
    EXPECT_EQ(powers(4, 30), (std::vector<int>{0, 0, 4}));
    EXPECT_EQ(powers(4, 34), (std::vector<int>{0, 0, 0}));
}

// Numbers go into expression text in their shortest form that reads back exactly.
TEST(PovPolynomial, NumbersReadBackExactly) {
    EXPECT_EQ(expression_number(-0.25), "(-0.25)");
    EXPECT_EQ(expression_number(0.1), "(0.1)");
    EXPECT_EQ(expression_number(1), "(1)");
    const double third = 1.0 / 3;
    const std::string text = expression_number(third);
    EXPECT_EQ(std::stod(text.substr(1, text.size() - 2)), third);
}

TEST(PovPolynomial, TextEvaluatesToThePolynomial) {
    // The torus of torus.pov: (x^2 + y^2 + z^2)^2 - 104 x^2 + 56 y^2 - 104 z^2 + 784, whose
    // tube (R^2 = 40, r^2 = 12) passes through (sqrt(40) + sqrt(12), 0, 0).
    std::vector<double> c(35, 0);
    c[0] = 1, c[4] = 2, c[7] = 2, c[9] = -104, c[20] = 1, c[23] = 2, c[25] = 56, c[30] = 1;
    c[32] = -104, c[34] = 784;
    const std::string text = polynomial_text(4, c);
    EXPECT_EQ(text.substr(0, 24), "(1)*x^4 + (2)*x^2*y^2 + ");
    auto compiled = compile_expression(text, {});
    ASSERT_TRUE(std::holds_alternative<Expression>(compiled));
    const Expression& f = std::get<Expression>(compiled);
    const float outer = float(std::sqrt(40.0) + std::sqrt(12.0));
    EXPECT_NEAR(f.value(Point3{outer, 0, 0}), 0, 1e-2);
    EXPECT_LT(f.value(Point3{float(std::sqrt(40.0)), 0, 0}), 0);  // the tube's centre: inside
    EXPECT_GT(f.value(Point3{0, 0, 0}), 0);                       // the hole: outside
    EXPECT_EQ(polynomial_text(2, std::vector<double>(10, 0)), "0");
}

}  // namespace
}  // namespace glint
