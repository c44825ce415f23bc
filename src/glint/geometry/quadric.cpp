// The quadric along the ray as a quadratic in double, about the middle of its chord through the
// clipping box, polished by Newton and clipped to the box; the gradient as its normal.
#include "glint/geometry/quadric.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "glint/math/quadratic.h"

namespace glint {

namespace {

// The coefficients in double, named as in the equation.
struct Terms {
    double a, b, c, d, e, f, g, h, i, j;
};

Terms terms_of(const Quadric& quadric) {
    const auto& k = quadric.coefficients;
    return {k[0], k[1], k[2], k[3], k[4], k[5], k[6], k[7], k[8], k[9]};
}

// The second-order part alone, Q(v) = A vx^2 + ... + F vy vz: alpha of the ray's quadratic.
double second_order(const Terms& q, double x, double y, double z) {
    return q.a * x * x + q.b * y * y + q.c * z * z + q.d * x * y + q.e * x * z + q.f * y * z;
}

double value(const Terms& q, double x, double y, double z) {
    return second_order(q, x, y, z) + q.g * x + q.h * y + q.i * z + q.j;
}

std::array<double, 3> gradient(const Terms& q, double x, double y, double z) {
    return {2 * q.a * x + q.d * y + q.e * z + q.g, 2 * q.b * y + q.d * x + q.f * z + q.h,
            2 * q.c * z + q.e * x + q.f * y + q.i};
}

}  // namespace

Bounds3 inside_extent(const std::array<float, 10>& c) {
    const Bounds3 everywhere{{-kInfinity, -kInfinity, -kInfinity},
                             {kInfinity, kInfinity, kInfinity}};
    if (c[3] != 0 || c[4] != 0 || c[5] != 0) return everywhere;
    double k = -double(c[9]), center[3] = {0, 0, 0};
    for (int i = 0; i < 3; ++i) {
        const double a = c[std::size_t(i)], g = c[std::size_t(6 + i)];
        if (a < 0 || (a == 0 && g != 0)) return everywhere;
        if (a > 0) {
            center[i] = -g / (2 * a);
            k += g * g / (4 * a);
        }
    }
    if (!(k > 0)) return {};
    Bounds3 box = everywhere;
    for (int i = 0; i < 3; ++i) {
        const double a = c[std::size_t(i)];
        if (a == 0) continue;
        const double half = std::sqrt(k / a);
        const float lo = float(center[i] - half), hi = float(center[i] + half);
        if (i == 0) box.min.x = lo, box.max.x = hi;
        if (i == 1) box.min.y = lo, box.max.y = hi;
        if (i == 2) box.min.z = lo, box.max.z = hi;
    }
    return box;
}

double quadric_value(const Quadric& quadric, double x, double y, double z) {
    return value(terms_of(quadric), x, y, z);
}

std::array<double, 3> quadric_gradient(const Quadric& quadric, double x, double y, double z) {
    return gradient(terms_of(quadric), x, y, z);
}

Bounds3 Quadric::bounds() const { return clip; }

std::optional<ShapeHit> Quadric::intersect(const Ray& ray, Interval t_range) const {
    const auto inside = intersect_slabs(clip, ray, t_range);
    if (!inside) return std::nullopt;
    const Terms q = terms_of(*this);
    // The origin moved to the middle of the chord through the box, in double.
    const double t_shift = 0.5 * (double{inside->min} + inside->max);
    const double dx = ray.direction.x, dy = ray.direction.y, dz = ray.direction.z;
    const double ox = ray.origin.x + t_shift * dx, oy = ray.origin.y + t_shift * dy,
                 oz = ray.origin.z + t_shift * dz;
    // f(O + s R) = Q(R) s^2 + (grad f(O).R) s + f(O).
    const double alpha = second_order(q, dx, dy, dz);
    const auto grad = gradient(q, ox, oy, oz);
    const double beta = grad[0] * dx + grad[1] * dy + grad[2] * dz;
    const double gamma = value(q, ox, oy, oz);
    // In double: over a far box (an unbounded quadric cut 10^5 out) the discriminant is a small
    // difference of numbers near 10^20, which float coefficients would turn into noise.
    const auto roots = solve_quadratic_double(alpha, beta, gamma);
    if (!roots) return std::nullopt;
    for (double s : {roots->t0, roots->t1}) {
        // A Newton step in double removes the rounding of the float coefficients. It is kept
        // only when it lowers the residual: at a double root (a tangent ray) the slope vanishes.
        const auto residual = [&](double root) { return (alpha * root + beta) * root + gamma; };
        const double polished = s - residual(s) / (2 * alpha * s + beta);
        if (std::abs(residual(polished)) < std::abs(residual(s))) s = polished;
        const auto t = static_cast<float>(t_shift + s);
        if (!t_range.contains(t)) continue;
        const double x = ox + s * dx, y = oy + s * dy, z = oz + s * dz;
        if (x >= clip.min.x && x <= clip.max.x && y >= clip.min.y && y <= clip.max.y &&
            z >= clip.min.z && z <= clip.max.z) {
            return ShapeHit{t};
        }
    }
    return std::nullopt;
}

SurfacePoint Quadric::surface_at(const Ray& ray, const ShapeHit& hit) const {
    const Terms q = terms_of(*this);
    const Point3 p = ray.at(hit.t);
    double x = p.x, y = p.y, z = p.z;
    // Newton onto f = 0 along the gradient: p - f grad f / |grad f|^2 removes the error of t.
    auto grad = gradient(q, x, y, z);
    double grad2 = grad[0] * grad[0] + grad[1] * grad[1] + grad[2] * grad[2];
    if (grad2 > 0) {
        const double step = value(q, x, y, z) / grad2;
        x -= step * grad[0];
        y -= step * grad[1];
        z -= step * grad[2];
        grad = gradient(q, x, y, z);
        grad2 = grad[0] * grad[0] + grad[1] * grad[1] + grad[2] * grad[2];
    }
    SurfacePoint sp;
    sp.p = {static_cast<float>(x), static_cast<float>(y), static_cast<float>(z)};
    if (grad2 > 0) {
        const double inv = 1 / std::sqrt(grad2);
        sp.normal = {static_cast<float>(grad[0] * inv), static_cast<float>(grad[1] * inv),
                     static_cast<float>(grad[2] * inv)};
    } else {
        sp.normal = Normal3(-normalize(ray.direction));
    }
    sp.shading_normal = sp.normal;
    const Vector3 size = clip.diagonal();
    const auto across = [](float coordinate, float low, float extent) {
        return extent > 0 ? std::clamp((coordinate - low) / extent, 0.0f, 1.0f) : 0.0f;
    };
    sp.uv = {across(sp.p.x, clip.min.x, size.x), across(sp.p.z, clip.min.z, size.z)};
    return sp;
}

std::string describe_problem(const Quadric& quadric) {
    std::ostringstream out;
    const auto& k = quadric.coefficients;
    constexpr const char* kNames = "ABCDEFGHIJ";
    for (int i = 0; i < 10; ++i) {
        if (!std::isfinite(k[i])) {
            out << "quadric coefficient " << kNames[i] << " must be finite, got " << k[i];
            return out.str();
        }
    }
    if (std::all_of(k.begin(), k.begin() + 9, [](float c) { return c == 0; })) {
        out << "quadric coefficients A to I must not all be 0: the equation has no surface";
    } else if (!quadric.clip.is_finite() || quadric.clip.is_empty()) {
        out << "quadric clip box must be finite with min <= max on every axis";
    }
    return out.str();
}

}  // namespace glint
