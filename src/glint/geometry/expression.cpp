// Evaluation of compiled expressions: one interpreter loop over the postfix program, run with
// different kinds of number (double, dual numbers, intervals, intervals with derivatives).
// The value stack is a fixed array of Expression::kMaxStack entries: nothing is allocated.
#include "glint/geometry/expression.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "glint/sampling/perlin_noise.h"

namespace glint {

namespace {

// a^n by repeated squaring for small n: exact for the squares that dominate implicit surfaces.
double power_int(double a, int n) {
    if (n < 0 || n > 64) return std::pow(a, double(n));
    double result = 1, base = a;
    for (unsigned k = unsigned(n); k != 0; k >>= 1) {
        if (k & 1) result *= base;
        base *= base;
    }
    return result;
}

// Perlin's noise is at most 2 in magnitude (a blend of eight terms g . d, each at most 2) and
// each of its partial derivatives at most 8.5 (the blend's weights change by 2 |fade'| <= 3.75
// along an axis, times 2, plus the gradients' own components, at most 1).
constexpr double kNoiseBound = 2, kNoiseSlope = 8.5;

double noise_at(double x, double y, double z) {
    return perlin_noise(Point3{float(x), float(y), float(z)});
}

// An enclosure of the noise over a box: its value at the centre, give or take the slope bound
// over the half-widths (and the centre's rounding to float, and the noise's own in float).
RealInterval noise_range(RealInterval x, RealInterval y, RealInterval z) {
    if (x.is_empty() || y.is_empty() || z.is_empty()) return RealInterval::empty();
    const RealInterval all{-kNoiseBound, kNoiseBound};
    const double cx = 0.5 * (x.lo + x.hi), cy = 0.5 * (y.lo + y.hi), cz = 0.5 * (z.lo + z.hi);
    const double spread = 0.5 * (x.width() + y.width() + z.width()) +
                          3 * std::max({std::abs(cx), std::abs(cy), std::abs(cz)}) * 0x1p-23;
    if (!std::isfinite(spread)) return all;
    const double c = noise_at(cx, cy, cz), margin = kNoiseSlope * spread * (1 + 1e-12) + 1e-5;
    return intersect({c - margin, c + margin}, all);
}

// The interpreter. A supplies the number type (A::Value) and its operations.
template <typename A>
typename A::Value run(std::span<const ExpressionInstruction> program, A& a,
                      const typename A::Value& x, const typename A::Value& y,
                      const typename A::Value& z) {
    // Uninitialised storage: every slot is written before it is read, and zeroing 64 values
    // per evaluation would cost as much as a short program.
    union Stack {
        Stack() {}
        typename A::Value slots[Expression::kMaxStack];
    } storage;
    auto& stack = storage.slots;
    int top = 0;  // compile_expression proved 0 < top <= kMaxStack throughout
    for (const ExpressionInstruction& in : program) {
        auto& last = stack[top > 0 ? top - 1 : 0];  // the operand of unary operators
        switch (in.op) {
            case ExpressionOp::kConstant:
                stack[top++] = a.constant(in.value);
                break;
            case ExpressionOp::kX:
                stack[top++] = x;
                break;
            case ExpressionOp::kY:
                stack[top++] = y;
                break;
            case ExpressionOp::kZ:
                stack[top++] = z;
                break;
            case ExpressionOp::kNegate:
                last = a.negate(last);
                break;
            case ExpressionOp::kPowerInteger:
                last = a.power_int(last, in.exponent);
                break;
            case ExpressionOp::kPowerConstant:
                last = a.power_constant(last, in.value);
                break;
            case ExpressionOp::kSin:
                last = a.sin(last);
                break;
            case ExpressionOp::kCos:
                last = a.cos(last);
                break;
            case ExpressionOp::kExp:
                last = a.exp(last);
                break;
            case ExpressionOp::kLog:
                last = a.log(last);
                break;
            case ExpressionOp::kSqrt:
                last = a.sqrt(last);
                break;
            case ExpressionOp::kAbs:
                last = a.abs(last);
                break;
            case ExpressionOp::kFloor:
                last = a.floor(last);
                break;
            case ExpressionOp::kTrunc:
                last = a.trunc(last);
                break;
            case ExpressionOp::kNoise:
                top -= 2;
                stack[top - 1] = a.noise(stack[top - 1], stack[top], stack[top + 1]);
                break;
            default: {
                --top;
                auto& l = stack[top - 1];
                const auto& r = stack[top];
                switch (in.op) {
                    case ExpressionOp::kAdd:
                        l = a.add(l, r);
                        break;
                    case ExpressionOp::kSubtract:
                        l = a.subtract(l, r);
                        break;
                    case ExpressionOp::kMultiply:
                        l = a.multiply(l, r);
                        break;
                    case ExpressionOp::kDivide:
                        l = a.divide(l, r);
                        break;
                    case ExpressionOp::kPower:
                        l = a.power(l, r);
                        break;
                    case ExpressionOp::kMin:
                        l = a.min(l, r);
                        break;
                    case ExpressionOp::kMax:
                        l = a.max(l, r);
                        break;
                    case ExpressionOp::kAtan2:
                        l = a.atan2(l, r);
                        break;
                    default:
                        break;
                }
            }
        }
    }
    return stack[0];
}

// Plain doubles: IEEE semantics, NaN where undefined.
struct Real {
    using Value = double;
    static double constant(double c) { return c; }
    static double negate(double a) { return -a; }
    static double add(double a, double b) { return a + b; }
    static double subtract(double a, double b) { return a - b; }
    static double multiply(double a, double b) { return a * b; }
    static double divide(double a, double b) { return a / b; }
    static double power_int(double a, int n) { return glint::power_int(a, n); }
    static double power_constant(double a, double p) { return std::pow(a, p); }
    static double power(double a, double b) { return std::pow(a, b); }
    static double sin(double a) { return std::sin(a); }
    static double cos(double a) { return std::cos(a); }
    static double exp(double a) { return std::exp(a); }
    static double log(double a) { return std::log(a); }
    static double sqrt(double a) { return std::sqrt(a); }
    static double abs(double a) { return std::abs(a); }
    static double floor(double a) { return std::floor(a); }
    static double trunc(double a) { return std::trunc(a); }
    static double min(double a, double b) { return std::min(a, b); }
    static double max(double a, double b) { return std::max(a, b); }
    static double atan2(double a, double b) { return std::atan2(a, b); }
    static double noise(double a, double b, double c) { return noise_at(a, b, c); }
};

// Forward-mode dual numbers with N partial derivatives: v + sum d_i eps_i, eps_i eps_j = 0.
// Each rule is the chain rule of its function; abs, min and max take one side at ties.
template <int N>
struct Dual {
    struct Value {
        double v = 0;
        std::array<double, N> d{};
    };
    static Value scaled(const Value& a, double value, double factor) {
        Value r{value};
        for (int i = 0; i < N; ++i) r.d[i] = a.d[i] * factor;
        return r;
    }
    static Value constant(double c) { return {c}; }
    static Value negate(const Value& a) { return scaled(a, -a.v, -1); }
    static Value add(const Value& a, const Value& b) {
        Value r{a.v + b.v};
        for (int i = 0; i < N; ++i) r.d[i] = a.d[i] + b.d[i];
        return r;
    }
    static Value subtract(const Value& a, const Value& b) { return add(a, negate(b)); }
    static Value multiply(const Value& a, const Value& b) {
        Value r{a.v * b.v};
        for (int i = 0; i < N; ++i) r.d[i] = a.d[i] * b.v + a.v * b.d[i];
        return r;
    }
    static Value divide(const Value& a, const Value& b) {  // (a' - (a/b) b') / b
        Value r{a.v / b.v};
        for (int i = 0; i < N; ++i) r.d[i] = (a.d[i] - r.v * b.d[i]) / b.v;
        return r;
    }
    static Value power_int(const Value& a, int n) {
        if (n == 0) return {1};
        return scaled(a, glint::power_int(a.v, n), n * glint::power_int(a.v, n - 1));
    }
    static Value power_constant(const Value& a, double p) {
        return scaled(a, std::pow(a.v, p), p * std::pow(a.v, p - 1));
    }
    static Value power(const Value& a, const Value& b) {  // d(a^b) = a^b (b' log a + b a'/a)
        Value r{std::pow(a.v, b.v)};
        const double log_a = std::log(a.v);
        for (int i = 0; i < N; ++i) r.d[i] = r.v * (b.d[i] * log_a + b.v * a.d[i] / a.v);
        return r;
    }
    static Value sin(const Value& a) { return scaled(a, std::sin(a.v), std::cos(a.v)); }
    static Value cos(const Value& a) { return scaled(a, std::cos(a.v), -std::sin(a.v)); }
    static Value exp(const Value& a) {
        const double e = std::exp(a.v);
        return scaled(a, e, e);
    }
    static Value log(const Value& a) { return scaled(a, std::log(a.v), 1 / a.v); }
    static Value sqrt(const Value& a) {
        const double s = std::sqrt(a.v);
        return scaled(a, s, 0.5 / s);
    }
    static Value abs(const Value& a) { return a.v < 0 ? negate(a) : a; }
    // Steps: flat between them (the derivative at a step, which does not exist, taken as 0).
    static Value floor(const Value& a) { return {std::floor(a.v)}; }
    static Value trunc(const Value& a) { return {std::trunc(a.v)}; }
    static Value min(const Value& a, const Value& b) { return b.v < a.v ? b : a; }
    static Value max(const Value& a, const Value& b) { return b.v > a.v ? b : a; }
    static Value atan2(const Value& a, const Value& b) {  // d = (b a' - a b') / (a^2 + b^2)
        Value r{std::atan2(a.v, b.v)};
        const double r2 = a.v * a.v + b.v * b.v;
        for (int i = 0; i < N; ++i) r.d[i] = (b.v * a.d[i] - a.v * b.d[i]) / r2;
        return r;
    }
    static Value noise(const Value& a, const Value& b, const Value& c) {
        const Point3 p{float(a.v), float(b.v), float(c.v)};
        const Vector3 g = perlin_noise_gradient(p);
        Value r{perlin_noise(p)};
        for (int i = 0; i < N; ++i) r.d[i] = g.x * a.d[i] + g.y * b.d[i] + g.z * c.d[i];
        return r;
    }
};

// Plain intervals: enclosures of the value only.
struct Intervals {
    using Value = RealInterval;
    static Value constant(double c) { return RealInterval::point(c); }
    static Value negate(Value a) { return -a; }
    static Value add(Value a, Value b) { return a + b; }
    static Value subtract(Value a, Value b) { return a - b; }
    static Value multiply(Value a, Value b) { return a * b; }
    static Value divide(Value a, Value b) { return a / b; }
    static Value power_int(Value a, int n) { return glint::pow(a, n); }
    static Value power_constant(Value a, double p) { return glint::pow(a, p); }
    static Value power(Value a, Value b) { return glint::pow(a, b); }
    static Value sin(Value a) { return glint::sin(a); }
    static Value cos(Value a) { return glint::cos(a); }
    static Value exp(Value a) { return glint::exp(a); }
    static Value log(Value a) { return glint::log(a); }
    static Value sqrt(Value a) { return glint::sqrt(a); }
    static Value abs(Value a) { return glint::abs(a); }
    static Value floor(Value a) { return glint::floor(a); }
    static Value trunc(Value a) { return glint::trunc(a); }
    static Value min(Value a, Value b) { return glint::min(a, b); }
    static Value max(Value a, Value b) { return glint::max(a, b); }
    static Value atan2(Value a, Value b) { return glint::atan2(a, b); }
    static Value noise(Value a, Value b, Value c) { return noise_range(a, b, c); }
};

// Intervals with an enclosure of the derivative along one direction (the ray parameter t).
// Every derivative rule is the pointwise chain rule evaluated in interval arithmetic, hence an
// enclosure of the derivative wherever it exists; where abs, min or max have a kink inside the
// interval the rule takes the hull of both sides (Clarke's generalised derivative), so the
// mean value theorem still holds for the result. `continuous` records whether any operation
// met a pole or the edge of its domain.
struct IntervalSlopes {
    struct Value {
        RealInterval v;
        RealInterval d;
    };
    bool continuous = true;

    static Value constant(double c) { return {RealInterval::point(c), {0, 0}}; }
    static Value negate(const Value& a) { return {-a.v, -a.d}; }
    static Value add(const Value& a, const Value& b) { return {a.v + b.v, a.d + b.d}; }
    static Value subtract(const Value& a, const Value& b) { return {a.v - b.v, a.d - b.d}; }
    static Value multiply(const Value& a, const Value& b) {
        return {a.v * b.v, a.d * b.v + a.v * b.d};
    }
    Value divide(const Value& a, const Value& b) {
        if (!b.v.excludes_zero()) continuous = false;
        const RealInterval q = a.v / b.v;
        return {q, (a.d - q * b.d) / b.v};
    }
    Value power_int(const Value& a, int n) {
        if (n == 0) return constant(1);
        if (n < 0 && !a.v.excludes_zero()) continuous = false;
        return {glint::pow(a.v, n), RealInterval::point(n) * glint::pow(a.v, n - 1) * a.d};
    }
    Value power_constant(const Value& a, double p) {
        if (p > 0 ? a.v.lo < 0 : a.v.lo <= 0) continuous = false;
        return {glint::pow(a.v, p), RealInterval::point(p) * glint::pow(a.v, p - 1) * a.d};
    }
    Value power(const Value& a, const Value& b) {
        if (!(a.v.lo > 0)) continuous = false;
        const RealInterval r = glint::pow(a.v, b.v);
        const RealInterval base = intersect(a.v, {0, RealInterval::whole().hi});
        return {r, r * (b.d * glint::log(base) + b.v * a.d / base)};
    }
    static Value sin(const Value& a) { return {glint::sin(a.v), glint::cos(a.v) * a.d}; }
    static Value cos(const Value& a) { return {glint::cos(a.v), -(glint::sin(a.v) * a.d)}; }
    static Value exp(const Value& a) {
        const RealInterval e = glint::exp(a.v);
        return {e, e * a.d};
    }
    Value log(const Value& a) {
        if (!(a.v.lo > 0)) continuous = false;
        return {glint::log(a.v), a.d / intersect(a.v, {0, RealInterval::whole().hi})};
    }
    Value sqrt(const Value& a) {
        if (a.v.lo < 0) continuous = false;
        const RealInterval s = glint::sqrt(a.v);
        return {s, a.d / (RealInterval::point(2) * s)};
    }
    static Value abs(const Value& a) {
        if (a.v.lo >= 0) return a;
        if (a.v.hi <= 0) return negate(a);
        return {glint::abs(a.v), hull(a.d, -a.d)};
    }
    // Flat between steps; a step inside the interval breaks continuity.
    Value floor(const Value& a) {
        const RealInterval f = glint::floor(a.v);
        if (f.lo != f.hi) continuous = false;
        return {f, {0, 0}};
    }
    Value trunc(const Value& a) {
        const RealInterval f = glint::trunc(a.v);
        if (f.lo != f.hi) continuous = false;
        return {f, {0, 0}};
    }
    static Value min(const Value& a, const Value& b) {
        if (a.v.hi <= b.v.lo) return a;
        if (b.v.hi <= a.v.lo) return b;
        return {glint::min(a.v, b.v), hull(a.d, b.d)};
    }
    static Value max(const Value& a, const Value& b) {
        if (a.v.lo >= b.v.hi) return a;
        if (b.v.lo >= a.v.hi) return b;
        return {glint::max(a.v, b.v), hull(a.d, b.d)};
    }
    Value atan2(const Value& a, const Value& b) {
        if (!atan2_continuous(a.v, b.v)) continuous = false;
        const RealInterval r2 = glint::pow(a.v, 2) + glint::pow(b.v, 2);
        return {glint::atan2(a.v, b.v), (b.v * a.d - a.v * b.d) / r2};
    }
    static Value noise(const Value& a, const Value& b, const Value& c) {
        const RealInterval slope{-kNoiseSlope, kNoiseSlope};
        return {noise_range(a.v, b.v, c.v), slope * a.d + slope * b.d + slope * c.d};
    }
};

}  // namespace

double Expression::value(double x, double y, double z) const {
    Real a;
    return run(program_, a, x, y, z);
}

RealInterval Expression::range(RealInterval x, RealInterval y, RealInterval z) const {
    Intervals a;
    return run(program_, a, x, y, z);
}

Expression::Gradient Expression::gradient(double x, double y, double z) const {
    using D = Dual<3>;
    D a;
    const D::Value r =
        run(program_, a, D::Value{x, {1, 0, 0}}, D::Value{y, {0, 1, 0}}, D::Value{z, {0, 0, 1}});
    return {r.v, r.d[0], r.d[1], r.d[2]};
}

Expression::RayValue Expression::along_ray(const Ray& ray, double t) const {
    using D = Dual<1>;
    D a;
    const auto coordinate = [&](int axis) {
        return D::Value{double(ray.origin[axis]) + t * double(ray.direction[axis]),
                        {double(ray.direction[axis])}};
    };
    const D::Value r = run(program_, a, coordinate(0), coordinate(1), coordinate(2));
    return {r.v, r.d[0]};
}

Expression::RaySegment Expression::along_ray(const Ray& ray, RealInterval t) const {
    IntervalSlopes a;
    const auto coordinate = [&](int axis) {
        const RealInterval d = RealInterval::point(ray.direction[axis]);
        return IntervalSlopes::Value{RealInterval::point(ray.origin[axis]) + t * d, d};
    };
    const IntervalSlopes::Value r = run(program_, a, coordinate(0), coordinate(1), coordinate(2));
    return {r.v, r.d, a.continuous};
}

RealInterval Expression::enclose_along_ray(const Ray& ray, double t) const {
    Intervals a;
    const RealInterval ti = RealInterval::point(t);
    const auto coordinate = [&](int axis) {
        return RealInterval::point(ray.origin[axis]) +
               ti * RealInterval::point(ray.direction[axis]);
    };
    return run(program_, a, coordinate(0), coordinate(1), coordinate(2));
}

}  // namespace glint
