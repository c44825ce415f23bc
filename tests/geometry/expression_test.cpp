#include "glint/geometry/expression.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <string>

#include "glint/sampling/perlin_noise.h"

namespace glint {
namespace {

Expression compile(std::string_view source, const ExpressionConstants& constants = {}) {
    auto result = compile_expression(source, constants);
    if (auto* error = std::get_if<ExpressionError>(&result)) {
        ADD_FAILURE() << source << ": " << error->message << " at " << error->offset;
        return std::get<Expression>(compile_expression("0"));
    }
    return std::get<Expression>(std::move(result));
}

ExpressionError error_of(std::string_view source, const ExpressionConstants& constants = {}) {
    auto result = compile_expression(source, constants);
    if (auto* error = std::get_if<ExpressionError>(&result)) return *error;
    ADD_FAILURE() << source << " compiled";
    return {};
}

double eval(std::string_view source, double x = 0, double y = 0, double z = 0) {
    return compile(source).value(x, y, z);
}

// The torus of the task: major radius R = 2 around y, minor radius r = 0.5. On the outer
// equator (2.5, 0, 0): (6.25 + 4 - 0.25)^2 - 4 * 4 * 6.25 = 100 - 100 = 0. At the centre:
// (4 - 0.25)^2 = 14.0625.
TEST(Expression, TorusWithNamedConstants) {
    const Expression torus =
        compile("(x^2 + y^2 + z^2 + R^2 - r^2)^2 - 4*R^2*(x^2 + z^2)", {{"R", 2}, {"r", 0.5}});
    EXPECT_DOUBLE_EQ(torus.value(2.5, 0, 0), 0);
    EXPECT_DOUBLE_EQ(torus.value(0, 0, 0), 14.0625);
    EXPECT_DOUBLE_EQ(torus.value(0, 0.5, 2), 0);  // top of the tube
    EXPECT_LT(torus.value(2, 0, 0), 0);           // inside the tube: f < 0
}

TEST(Expression, PrecedenceAndAssociativity) {
    EXPECT_EQ(eval("-x^2", 3), -9);  // -(x^2), as in mathematics
    EXPECT_EQ(eval("-2^2"), -4);
    EXPECT_EQ(eval("(-2)^2"), 4);
    EXPECT_EQ(eval("2^3^2"), 512);  // 2^(3^2): ^ is right-associative
    EXPECT_EQ(eval("x^-2", 2), 0.25);
    EXPECT_EQ(eval("1 - 2 - 3"), -4);  // left-associative
    EXPECT_EQ(eval("8 / 4 / 2"), 1);
    EXPECT_EQ(eval("2 * 3 + 4 * 5"), 26);
    EXPECT_EQ(eval("2 * (3 + 4) * 5"), 70);
    EXPECT_EQ(eval("--x", 7), 7);
    EXPECT_EQ(eval("+x - -y", 1, 2), 3);
    EXPECT_EQ(eval("2*x^2*y", 3, 5), 90);
}

TEST(Expression, NumbersAreCStyle) {
    EXPECT_EQ(eval("1e3"), 1000);
    EXPECT_EQ(eval("1.5e-3"), 0.0015);
    EXPECT_EQ(eval("2.5E+2"), 250);
    EXPECT_EQ(eval(".5"), 0.5);
    EXPECT_EQ(eval("5."), 5);
    EXPECT_EQ(eval("  42\t"), 42);
}

TEST(Expression, FunctionsAndPi) {
    EXPECT_DOUBLE_EQ(eval("sin(x)", 0.5), std::sin(0.5));
    EXPECT_DOUBLE_EQ(eval("cos(x)", 0.5), std::cos(0.5));
    EXPECT_DOUBLE_EQ(eval("exp(x)", 0.5), std::exp(0.5));
    EXPECT_DOUBLE_EQ(eval("log(x)", 0.5), std::log(0.5));
    EXPECT_DOUBLE_EQ(eval("sqrt(x)", 0.5), std::sqrt(0.5));
    EXPECT_EQ(eval("abs(x)", -0.5), 0.5);
    EXPECT_EQ(eval("min(x, y)", 1, 2), 1);
    EXPECT_EQ(eval("max(x, y)", 1, 2), 2);
    EXPECT_DOUBLE_EQ(eval("sin(pi/2)"), 1);
    EXPECT_DOUBLE_EQ(eval("sin(x) + sin(y) + sin(z)", 1, 2, 3),
                     std::sin(1) + std::sin(2) + std::sin(3));
    EXPECT_TRUE(std::isnan(eval("sqrt(x)", -1)));  // undefined: NaN, not a crash
    EXPECT_TRUE(std::isinf(eval("1/x", 0)));
}

TEST(Expression, ConstantPartsAreFoldedAtCompileTime) {
    // 2*3 + x: [6, x, +]. R^2 becomes 4; x^2 is an integer power, x^0.5 a constant power.
    EXPECT_EQ(compile("2*3 + x").program().size(), 3u);
    EXPECT_EQ(compile("R^2*x", {{"R", 2}}).program().size(), 3u);
    const Expression square = compile("x^2");
    ASSERT_EQ(square.program().size(), 2u);
    EXPECT_EQ(square.program()[1].op, ExpressionOp::kPowerInteger);
    EXPECT_EQ(square.program()[1].exponent, 2);
    EXPECT_EQ(compile("x^0.5").program()[1].op, ExpressionOp::kPowerConstant);
    EXPECT_EQ(compile("x^y").program()[2].op, ExpressionOp::kPower);
    EXPECT_EQ(compile("sin(pi) + x").program().size(), 3u);
    EXPECT_EQ(compile("x + y*z").stack_depth(), 3);
    EXPECT_EQ(compile("x*y + z").stack_depth(), 2);
}

TEST(Expression, UnknownFunctionSuggestsTheNearestName) {
    const ExpressionError e = error_of("2 + son(x)");
    EXPECT_EQ(e.offset, 4u);
    EXPECT_EQ(e.length, 3u);
    EXPECT_EQ(e.message, "unknown function \"son\"");
    ASSERT_EQ(e.notes.size(), 1u);
    EXPECT_EQ(e.notes[0],
              "functions are: abs, atan2, cos, exp, floor, log, max, min, noise, sin, sqrt, trunc "
              "(did you mean \"sin\"?)");
    EXPECT_EQ(error_of("frobnicate(x)").notes[0],
              "functions are: abs, atan2, cos, exp, floor, log, max, min, noise, sin, sqrt, trunc");
}

TEST(Expression, UnknownNameListsCoordinatesAndConstants) {
    const ExpressionError e = error_of("x + q", {{"R", 2}, {"r", 1}});
    EXPECT_EQ(e.offset, 4u);
    EXPECT_EQ(e.length, 1u);
    EXPECT_EQ(e.message, "unknown name \"q\"");
    ASSERT_EQ(e.notes.size(), 1u);
    EXPECT_EQ(e.notes[0], "names are: x, y, z, R, r, pi");
    EXPECT_EQ(error_of("radus * x", {{"radius", 2}}).notes[0],
              "names are: x, y, z, radius, pi (did you mean \"radius\"?)");
}

TEST(Expression, SyntaxErrorsPointAtTheirPlace) {
    struct Case {
        std::string source;
        std::size_t offset, length;
        std::string message;
    };
    const Case cases[] = {
        {"(x + 1", 6, 0, "expected \")\" before the end"},
        {"(x + 1 y", 7, 1, "expected \")\" before \"y\""},
        {"x +", 3, 0, "missing operand"},
        {"x + * y", 4, 1, "missing operand"},
        {"()", 1, 1, "missing operand"},
        {"max(x)", 0, 6, "max takes 2 arguments, got 1"},
        {"sin(x, y)", 0, 9, "sin takes 1 argument, got 2"},
        {"min()", 0, 5, "min takes 2 arguments, got 0"},
        {"x # y", 2, 1, "unexpected character \"#\""},
        {"x \xc3\xa9", 2, 2, "unexpected character \"\xc3\xa9\""},
        {"", 0, 0, "empty expression"},
        {"   ", 0, 3, "empty expression"},
        {"2x", 1, 1, "missing operator before \"x\""},
        {"x)", 1, 1, "unmatched \")\""},
        {"x, y", 1, 1, "\",\" outside a function call"},
        {"max(x y)", 6, 1, "expected \",\" or \")\" before \"y\""},
        {"sin + 1", 0, 3, "function \"sin\" needs its argument list"},
        {"x + 1/0", 4, 3, "\"1/0\" is infinite"},
        {"sqrt(-1) * x", 0, 8, "\"sqrt(-1)\" has no real value"},
        {"1e999 * x", 0, 5, "number \"1e999\" is out of range"},
        {"1e+x", 0, 4, "malformed number \"1e+x\""},
        {"2ex", 0, 3, "malformed number \"2ex\""},
    };
    for (const Case& c : cases) {
        const ExpressionError e = error_of(c.source);
        EXPECT_EQ(e.message, c.message) << c.source;
        EXPECT_EQ(e.offset, c.offset) << c.source;
        EXPECT_EQ(e.length, c.length) << c.source;
    }
    EXPECT_EQ(error_of("2x").notes.at(0), "multiplication is written with \"*\", as in 2*x");
}

TEST(Expression, SizeAndDepthAreBounded) {
    std::string nested = std::string(70, '(') + "x" + std::string(70, ')');
    EXPECT_EQ(error_of(nested).message, "expression nested too deeply (more than 64 levels)");
    EXPECT_EQ(error_of(nested).offset, 64u);
    compile(std::string(60, '(') + "x" + std::string(60, ')'));

    std::string long_sum = "x";
    for (int i = 0; i < 3000; ++i) long_sum += "+x";
    EXPECT_EQ(error_of(long_sum).message, "expression too long (more than 4096 operations)");
    std::string fits = "x";
    for (int i = 0; i < 2000; ++i) fits += "+x";
    EXPECT_EQ(compile(fits).value(1, 0, 0), 2001);

    // Three operands wait per parenthesis (sum, product, power): within the nesting limit,
    // but more values alive at once than the evaluation stack holds.
    std::string wide;
    for (int i = 0; i < 30; ++i) wide += "x+x*x^(";
    wide += "x" + std::string(30, ')');
    EXPECT_EQ(error_of(wide).message, "expression needs more than 64 values at once to evaluate");

    EXPECT_EQ(error_of(std::string(70000, ' ')).message,
              "expression too long (more than 65536 characters)");
}

TEST(Expression, ConstantsMustBeFiniteAndNotHideCoordinates) {
    EXPECT_EQ(error_of("x", {{"y", 1}}).message, "constant \"y\" would hide the coordinate y");
    EXPECT_EQ(error_of("x", {{"R", INFINITY}}).message, "constant \"R\" is not a finite number");
    EXPECT_EQ(eval("pi"), std::numbers::pi);
    EXPECT_EQ(compile("pi", {{"pi", 3}}).value(0, 0, 0), 3);  // the scene's own pi wins
}

// x^2 y + sin z at (1, 2, 0.5): gradient (2xy, x^2, cos z) = (4, 1, cos 0.5).
TEST(Expression, GradientIsExact) {
    const Expression f = compile("x^2*y + sin(z)");
    const Expression::Gradient g = f.gradient(1, 2, 0.5);
    EXPECT_DOUBLE_EQ(g.value, 2 + std::sin(0.5));
    EXPECT_DOUBLE_EQ(g.dx, 4);
    EXPECT_DOUBLE_EQ(g.dy, 1);
    EXPECT_DOUBLE_EQ(g.dz, std::cos(0.5));
    // d/dx of x / y = 1/y, d/dy = -x / y^2; d/dx of x^y = y x^(y-1), d/dy = x^y log x.
    const Expression::Gradient q = compile("x / y + x^y").gradient(2, 3, 0);
    EXPECT_DOUBLE_EQ(q.dx, 1.0 / 3 + 3 * 4);
    EXPECT_DOUBLE_EQ(q.dy, -2.0 / 9 + 8 * std::log(2.0));
}

// Every function's derivative rule against central differences, at random points.
TEST(Expression, GradientAgreesWithDifferenceQuotients) {
    const Expression f = compile(
        "sqrt(x^2 + 1) * exp(-y) / (2 + cos(z)) + log(abs(x) + 1)^1.5 - max(x, y)*min(y, z) "
        "+ (x^2 + 1)^(y / 3) + abs(z)^-1");
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> u(-2, 2);
    for (int i = 0; i < 200; ++i) {
        const double x = u(rng), y = u(rng), z = u(rng);
        const Expression::Gradient g = f.gradient(x, y, z);
        const double h = 1e-6;
        EXPECT_NEAR(g.dx, (f.value(x + h, y, z) - f.value(x - h, y, z)) / (2 * h),
                    1e-5 * (1 + std::abs(g.dx)));
        EXPECT_NEAR(g.dy, (f.value(x, y + h, z) - f.value(x, y - h, z)) / (2 * h),
                    1e-5 * (1 + std::abs(g.dy)));
        EXPECT_NEAR(g.dz, (f.value(x, y, z + h) - f.value(x, y, z - h)) / (2 * h),
                    1e-5 * (1 + std::abs(g.dz)));
    }
}

// atan2(a, b), the angle of (b, a): worked values, its gradient (-a, b) / (a^2 + b^2), and its
// jump along a = 0, b < 0, where a ray's segment is not continuous.
TEST(Expression, Atan2IsTheAngleOfAPoint) {
    const Expression f = compile("atan2(y, x)");
    EXPECT_NEAR(f.value(1, 1, 0), std::acos(-1.0) / 4, 1e-15);
    EXPECT_NEAR(f.value(-1, 0, 0), std::acos(-1.0), 1e-15);
    const Expression::Gradient g = f.gradient(1, 2, 0);
    EXPECT_NEAR(g.dx, -2.0 / 5, 1e-15);
    EXPECT_NEAR(g.dy, 1.0 / 5, 1e-15);
    EXPECT_NEAR(compile("atan2(1, 1)").value(0, 0, 0), std::acos(-1.0) / 4, 1e-15);  // folded
    const Ray up{{-1, -1, 0}, {0, 1, 0}};  // x = -1, y = t - 1: crosses the jump at t = 1
    EXPECT_FALSE(f.along_ray(up, RealInterval{0.5, 1.5}).continuous);
    const Expression::RaySegment before = f.along_ray(up, RealInterval{0.1, 0.5});
    EXPECT_TRUE(before.continuous);
    for (double t = 0.1; t <= 0.5; t += 0.05) {
        EXPECT_TRUE(before.value.contains(f.along_ray(up, t).value));
        EXPECT_TRUE(before.slope.contains(f.along_ray(up, t).slope));
    }
}

// floor and trunc: the whole numbers below and towards 0, flat between their steps, whose
// enclosures hold every value and whose segments are continuous only between steps.
TEST(Expression, FloorAndTruncAreStepsThatBreakContinuity) {
    EXPECT_EQ(eval("floor(x)", 2.5), 2);
    EXPECT_EQ(eval("floor(x)", -2.5), -3);
    EXPECT_EQ(eval("trunc(x)", -2.5), -2);
    EXPECT_EQ(eval("trunc(x)", 2.5), 2);
    // C's fmod by trunc, as POV-Ray's mod: -7.5 mod 2 is -1.5.
    EXPECT_DOUBLE_EQ(eval("x - 2*trunc(x/2)", -7.5), -1.5);
    EXPECT_EQ(eval("floor(2.7) + trunc(-2.7)"), 0);  // folded
    const Expression f = compile("floor(x) + y");
    const Expression::Gradient g = f.gradient(1.5, 2, 0);
    EXPECT_EQ(g.dx, 0);
    EXPECT_EQ(g.dy, 1);
    // Widened outwards by the sum's rounding.
    const RealInterval r = f.range({0.2, 2.5}, {0, 0}, {0, 0});
    EXPECT_NEAR(r.lo, 0, 1e-300);
    EXPECT_NEAR(r.hi, 2, 1e-15);
    EXPECT_EQ(compile("trunc(x)").range({-1.5, 0.5}, {0, 0}, {0, 0}), (RealInterval{-1, 0}));
    const Ray ray{{-1, 0.5f, 0.5f}, {1, 0, 0}};  // x = t - 1
    EXPECT_TRUE(f.along_ray(ray, RealInterval{1.1, 1.9}).continuous);
    EXPECT_FALSE(f.along_ray(ray, RealInterval{0.5, 1.5}).continuous);
    const Expression::RaySegment flat = compile("trunc(x)").along_ray(ray, RealInterval{0.5, 1.5});
    EXPECT_TRUE(flat.continuous);  // trunc is 0 all across (-0.5, 0.5)
    EXPECT_EQ(flat.slope, (RealInterval{0, 0}));
}

// noise(a, b, c) is Perlin's noise at (a, b, c): its value and exact gradient, folded when
// constant, and enclosures over boxes and ray segments that hold what it takes there.
TEST(Expression, NoiseIsPerlinsNoiseWithEnclosures) {
    const Expression f = compile("noise(2*x, y, z + 1)");
    const Point3 p{0.3f, 1.7f, -0.4f};
    EXPECT_DOUBLE_EQ(f.value(p.x, p.y, p.z), perlin_noise(Point3{0.6f, 1.7f, 0.6f}));
    const Vector3 g = perlin_noise_gradient(Point3{0.6f, 1.7f, 0.6f});
    const Expression::Gradient fg = f.gradient(p.x, p.y, p.z);
    EXPECT_NEAR(fg.dx, 2 * g.x, 1e-6);
    EXPECT_NEAR(fg.dy, g.y, 1e-6);
    EXPECT_NEAR(fg.dz, g.z, 1e-6);
    EXPECT_DOUBLE_EQ(compile("noise(0.5, 0.25, 0.125)").value(0, 0, 0),
                     perlin_noise(Point3{0.5f, 0.25f, 0.125f}));
    std::mt19937 rng(9);
    std::uniform_real_distribution<double> u(-20, 20), unit(0, 1);
    for (int i = 0; i < 300; ++i) {
        RealInterval box[3];
        for (auto& b : box) {
            const double a = u(rng), w = unit(rng) * unit(rng) * 3;
            b = {a, a + w};
        }
        const RealInterval r = f.range(box[0], box[1], box[2]);
        EXPECT_GE(r.lo, -2);
        EXPECT_LE(r.hi, 2);
        for (int j = 0; j < 10; ++j) {
            const double v = f.value(box[0].lo + unit(rng) * box[0].width(),
                                     box[1].lo + unit(rng) * box[1].width(),
                                     box[2].lo + unit(rng) * box[2].width());
            ASSERT_TRUE(r.contains(v)) << v;
        }
    }
    const Ray ray{{0.2f, -3, 1}, normalize(Vector3{1, 2, 0.5f})};
    const Expression::RaySegment s = f.along_ray(ray, RealInterval{0, 2});
    EXPECT_TRUE(s.continuous);
    for (double t = 0; t <= 2; t += 0.02) {
        EXPECT_TRUE(s.value.contains(f.along_ray(ray, t).value));
        EXPECT_TRUE(s.slope.contains(f.along_ray(ray, t).slope));
    }
}

TEST(Expression, RangeOverABox) {
    const Expression sphere = compile("x^2 + y^2 + z^2 - 1");
    const RealInterval around = sphere.range({-1, 1}, {-1, 1}, {-1, 1});
    EXPECT_LE(around.lo, -1);  // 0 + 0 + 0 - 1: even powers start at 0, not at -1
    EXPECT_NEAR(around.lo, -1, 1e-12);
    EXPECT_NEAR(around.hi, 2, 1e-12);
    const RealInterval away = sphere.range({2, 3}, {2, 3}, {2, 3});  // [11, 26]: no zero
    EXPECT_TRUE(away.excludes_zero());
    EXPECT_NEAR(away.lo, 11, 1e-12);
    EXPECT_TRUE(compile("sqrt(x)").range({-2, -1}, {0, 0}, {0, 0}).is_empty());
    EXPECT_TRUE(compile("1/x").range({-1, 1}, {0, 0}, {0, 0}).contains(1e300));
}

// The enclosures hold every point value, for an expression using every operation.
TEST(Expression, RangesEncloseSampledValues) {
    const Expression f = compile(
        "sin(3*x)*cos(y) + exp(z/2) - sqrt(abs(x*y)) + log(z^2 + 0.1) + min(x, z)^3 "
        "- max(y, 1/(z + 3))^2 + (x^2 + 0.5)^(y / 2) + (abs(y) + 1)^-1.5");
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> u(-2, 2), unit(0, 1);
    for (int i = 0; i < 300; ++i) {
        RealInterval box[3];
        for (auto& b : box) {
            const double a = u(rng), w = unit(rng) * unit(rng) * 2;
            b = {a, a + w};
        }
        const RealInterval r = f.range(box[0], box[1], box[2]);
        for (int j = 0; j < 20; ++j) {
            const double x = box[0].lo + unit(rng) * box[0].width();
            const double y = box[1].lo + unit(rng) * box[1].width();
            const double z = box[2].lo + unit(rng) * box[2].width();
            const double v = f.value(x, y, z);
            if (std::isfinite(v)) {
                ASSERT_TRUE(r.contains(v)) << v;
            }
        }
    }
}

// Along a ray: the point derivative is grad f . d, and the segment enclosures hold the
// sampled values and difference quotients.
TEST(Expression, AlongARay) {
    const Expression f = compile("x^2*y - sin(z) + x*z");
    const Ray ray{{0.5f, -1, 2}, normalize(Vector3{1, 2, -2})};
    const double t = 0.7;
    const Point3 p = ray.at(float(t));
    const Expression::RayValue rv = f.along_ray(ray, t);
    const Expression::Gradient g = f.gradient(p.x, p.y, p.z);
    EXPECT_NEAR(rv.value, g.value, 1e-6);
    EXPECT_NEAR(rv.slope, g.dx * ray.direction.x + g.dy * ray.direction.y + g.dz * ray.direction.z,
                1e-6);

    const Expression::RaySegment s = f.along_ray(ray, RealInterval{0.2, 1.4});
    EXPECT_TRUE(s.continuous);
    for (double a = 0.2; a < 1.39; a += 0.01) {
        EXPECT_TRUE(s.value.contains(f.along_ray(ray, a).value));
        EXPECT_TRUE(s.slope.contains(f.along_ray(ray, a).slope));
        EXPECT_TRUE(f.enclose_along_ray(ray, a).contains(f.along_ray(ray, a).value));
    }
}

TEST(Expression, SegmentsThroughPolesOrDomainEdgesAreNotContinuous) {
    const Ray ray{{-1, 0.5f, 0.5f}, {1, 0, 0}};  // x = t - 1
    const auto continuous = [&](std::string_view source, double t0, double t1) {
        return compile(source).along_ray(ray, RealInterval{t0, t1}).continuous;
    };
    EXPECT_FALSE(continuous("1/x", 0.5, 1.5));  // x crosses 0
    EXPECT_TRUE(continuous("1/x", 1.5, 2.5));
    EXPECT_FALSE(continuous("sqrt(x)", 0.5, 1.5));
    EXPECT_TRUE(continuous("sqrt(x)", 1.5, 2.5));
    EXPECT_FALSE(continuous("log(x)", 0.5, 1.5));
    EXPECT_FALSE(continuous("x^-2", 0.5, 1.5));
    EXPECT_FALSE(continuous("x^1.5", 0.5, 1.5));
    EXPECT_TRUE(continuous("y^x", 0.5, 1.5));  // base y = 0.5 > 0
    EXPECT_FALSE(continuous("x^y", 0.5, 1.5));
    EXPECT_TRUE(continuous("abs(x) + min(x, y) + x^3", 0.5, 1.5));
}

}  // namespace
}  // namespace glint
