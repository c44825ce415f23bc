// A real function f(x, y, z) written as text ("x^2 + y^2 + z^2 - 1"), compiled once into a flat
// postfix program and evaluated at points, over boxes (interval arithmetic) and with exact
// derivatives (forward-mode dual numbers). Implicit surfaces are the zeros of such functions.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <map>
#include <span>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "glint/math/interval_arithmetic.h"
#include "glint/math/ray.h"
#include "glint/math/vector.h"

namespace glint {

// What is wrong with a source text, and where: bytes [offset, offset + length) of the text.
// The scene loader turns the offset into file:line:col.
struct ExpressionError {
    std::size_t offset = 0;
    std::size_t length = 0;
    std::string message;             // e.g. unknown function "son"
    std::vector<std::string> notes;  // e.g. functions are: abs, cos, ... (did you mean "sin"?)
};

// Named constants a scene supplies (R = 2 makes "R^2" mean 4). They are folded into the program
// when it is compiled.
using ExpressionConstants = std::map<std::string, double, std::less<>>;

enum class ExpressionOp : std::uint8_t {
    kConstant,  // push value
    kX,
    kY,
    kZ,
    kNegate,
    kAdd,
    kSubtract,
    kMultiply,
    kDivide,
    kPowerInteger,   // a^n, n = exponent
    kPowerConstant,  // a^p, p = value, not an integer
    kPower,          // a^b
    kSin,
    kCos,
    kExp,
    kLog,
    kSqrt,
    kAbs,
    kMin,
    kMax,
    kAtan2,  // atan2(a, b): the angle of the point (b, a)
    kNoise,  // noise(a, b, c): Perlin's noise (sampling/perlin_noise.h) at the point (a, b, c)
    kFloor,  // the whole number at or below a
    kTrunc,  // a's whole part, towards 0
};

struct ExpressionInstruction {
    ExpressionOp op = ExpressionOp::kConstant;
    int exponent = 0;  // kPowerInteger
    double value = 0;  // kConstant, kPowerConstant
};

class Expression {
public:
    // Limits checked by compile_expression, so that evaluation needs only fixed arrays.
    static constexpr int kMaxStack = 64;              // values alive at once during evaluation
    static constexpr int kMaxNesting = 64;            // parentheses, calls, unary minus, ^ chains
    static constexpr std::size_t kMaxProgram = 4096;  // instructions after constant folding
    static constexpr std::size_t kMaxSource = 65536;  // bytes of source text

    // f at a point. NaN where f is undefined (sqrt(-1), log(-1), 0/0), +-inf at poles.
    double value(double x, double y, double z) const;
    double value(Point3 p) const { return value(p.x, p.y, p.z); }

    // An enclosure of f over the box x * y * z: every defined value of f there lies inside.
    // Empty when f is defined nowhere in the box.
    RealInterval range(RealInterval x, RealInterval y, RealInterval z) const;

    // f and its exact gradient at a point (forward-mode automatic differentiation).
    struct Gradient {
        double value = 0;
        double dx = 0, dy = 0, dz = 0;
    };
    Gradient gradient(double x, double y, double z) const;

    // Along a ray p(t) = origin + t direction, in double precision.
    // f(p(t)) and its derivative with respect to t.
    struct RayValue {
        double value = 0;
        double slope = 0;
    };
    RayValue along_ray(const Ray& ray, double t) const;
    // Enclosures of f(p(t)) and of d/dt f(p(t)) over t in [t.lo, t.hi]. `continuous` is true
    // when the evaluation proved f defined and continuous on the whole segment: no division by
    // an enclosure holding 0, no argument of sqrt, log or a fractional power reaching outside
    // its domain. Only then do the mean value theorem and the intermediate value theorem apply,
    // and the slope enclosure bounds the difference quotients of f (generalised derivatives of
    // abs, min and max included).
    struct RaySegment {
        RealInterval value;
        RealInterval slope;
        bool continuous = true;
    };
    RaySegment along_ray(const Ray& ray, RealInterval t) const;
    // Enclosure of f(p(t)) at a single t: the rigorous sign of f there.
    RealInterval enclose_along_ray(const Ray& ray, double t) const;

    std::span<const ExpressionInstruction> program() const { return program_; }
    int stack_depth() const { return stack_depth_; }
    const std::string& source() const { return source_; }

private:
    friend std::variant<Expression, ExpressionError> compile_expression(
        std::string_view source, const ExpressionConstants& constants);
    Expression() = default;

    std::vector<ExpressionInstruction> program_;
    int stack_depth_ = 0;
    std::string source_;
};

// Compiles `source` (grammar in docs/implicit-surfaces.md). Names are x, y, z, pi and the given
// constants, which must be finite and must not be called x, y or z. Never throws for bad
// source: every problem comes back as an ExpressionError.
std::variant<Expression, ExpressionError> compile_expression(
    std::string_view source, const ExpressionConstants& constants = {});

// The function names of the language, sorted: abs, atan2, cos, exp, floor, log, max, min,
// noise, sin, sqrt, trunc.
std::span<const std::string_view> expression_functions();

}  // namespace glint
