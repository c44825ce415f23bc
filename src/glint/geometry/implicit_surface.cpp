// The first root of f along a ray: depth-first interval subdivision of the ray parameter, left
// piece first (Mitchell 1990, "Robust ray intersection with interval arithmetic"; Snyder 1992),
// with safeguarded Newton on monotonic pieces. Contract and guarantees: docs/implicit-surfaces.md.
#include "glint/geometry/implicit_surface.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "glint/geometry/number_text.h"
#include "glint/geometry/spherical_uv.h"
#include "glint/math/safeguarded_newton.h"

namespace glint {

namespace {

// The sign of f at a single t, from an enclosure so that rounding cannot flip it: 0 when a
// finite enclosure holds 0 (a root at t as far as double precision can tell), kUndefined when
// f has no value there or the enclosure is unbounded (a pole: 1/0 encloses everything).
constexpr int kUndefined = 2;

class RootSearch {
public:
    RootSearch(const ImplicitSurface& s, const Ray& ray) : f_(*s.f), ray_(ray) {
        tolerance_ = s.tolerance > 0 ? double(s.tolerance) : 0.0;
    }

    int sign_at(double t) const {
        const RealInterval e = f_.enclose_along_ray(ray_, t);
        if (e.lo > 0) return 1;
        if (e.hi < 0) return -1;
        return e.is_empty() || !std::isfinite(e.lo) || !std::isfinite(e.hi) ? kUndefined : 0;
    }
    double value_at(double t) const { return f_.along_ray(ray_, t).value; }

    // Newton's target accuracy: below float resolution of t, and far below the tolerance.
    double x_tolerance(double a, double b) const {
        return 1e-8 * std::max(std::abs(a), std::abs(b)) + 1e-6 * tolerance_ + 1e-30;
    }

    // A root in [a, b] where f is continuous and sign(a) = -sign(b), both non-zero.
    double refine_continuous(double a, double b) const {
        const auto f = [&](double t) { return f_.along_ray(ray_, t); };
        const NewtonResult r =
            safeguarded_newton(f, a, b, value_at(a), value_at(b), x_tolerance(a, b));
        return std::clamp(r.x, a, b);
    }

    // Bisection where f may have a pole or a domain edge between a and b. A root makes |f|
    // shrink as the bracket closes; a pole or a jump does not. Accept only the former.
    std::optional<double> refine_discontinuous(double a, double b) const {
        double fa = value_at(a), fb = value_at(b);
        if (!(fa * fb < 0)) return std::nullopt;  // NaN or no sign change in double
        const double start = std::max(std::abs(fa), std::abs(fb));
        const double accuracy = x_tolerance(a, b);
        for (int i = 0; i < 200 && b - a > accuracy; ++i) {
            const double m = 0.5 * (a + b);
            const double fm = value_at(m);
            if (fm != fm) return std::nullopt;
            if (fm == 0) return m;
            ((fm < 0) == (fa < 0) ? a : b) = m;
            ((fm < 0) == (fa < 0) ? fa : fb) = fm;
        }
        if (std::max(std::abs(fa), std::abs(fb)) > 0.5 * start) return std::nullopt;
        return std::abs(fa) <= std::abs(fb) ? a : b;
    }

    // A piece on which f is continuous and strictly monotonic: a root iff the ends differ in
    // sign (intermediate value theorem), and then the only one.
    std::optional<double> resolve_monotonic(double a, double b) const {
        const int sa = sign_at(a), sb = sign_at(b);
        if (sa == 0) return a;
        if (sa == kUndefined || sb == kUndefined) return std::nullopt;
        if (sb == 0) return b;
        if (sa == sb) return std::nullopt;
        return refine_continuous(a, b);
    }

    // A tolerance-wide piece whose enclosure holds 0: a sign change among three samples is
    // refined to a root; otherwise, if f is continuous here, the ray passes within the
    // tolerance of a zero of f (a tangential root, or a feature thinner than the tolerance):
    // a hit at the sample nearest to zero.
    std::optional<double> resolve_leaf(double a, double b, bool continuous,
                                       ImplicitSearch::Found& found) const {
        const double m = 0.5 * (a + b);
        const std::array<double, 3> t{a, m, b};
        const std::array<int, 3> s{sign_at(a), sign_at(m), sign_at(b)};
        found = ImplicitSearch::Found::kSignChange;
        for (int i = 0; i < 3; ++i) {
            if (s[i] == 0) return t[i];
            if (i == 2 || s[i] == kUndefined || s[i + 1] == kUndefined || s[i] == s[i + 1] ||
                s[i + 1] == 0)
                continue;
            if (continuous) return refine_continuous(t[i], t[i + 1]);
            if (const auto root = refine_discontinuous(t[i], t[i + 1])) return root;
        }
        if (!continuous) return std::nullopt;
        found = ImplicitSearch::Found::kTangential;
        int best = 0;
        for (int i = 1; i < 3; ++i)
            if (std::abs(value_at(t[i])) < std::abs(value_at(t[best]))) best = i;
        return t[best];
    }

    double tolerance() const { return tolerance_; }
    const Expression& f() const { return f_; }

private:
    const Expression& f_;
    const Ray& ray_;
    double tolerance_ = 0;
};

}  // namespace

ImplicitSearch find_first_root(const ImplicitSurface& surface, const Ray& ray, Interval t_range) {
    ImplicitSearch search;
    if (!surface.f || !is_finite(ray.origin) || !is_finite(ray.direction)) return search;
    const auto clipped = intersect_slabs(surface.region, ray, t_range);
    if (!clipped || !std::isfinite(clipped->min) || !std::isfinite(clipped->max)) return search;

    const RootSearch root_search(surface, ray);
    const auto report = [&](double t, ImplicitSearch::Found found) {
        const float hit_t = std::clamp(float(t), clipped->min, clipped->max);
        search.hit = ShapeHit{hit_t};
        search.found = found;
        return search;
    };

    // Depth-first, left piece first: every piece before the current one has been proven free
    // of roots, so the first root found is the first along the ray. The stack never holds
    // more than one piece per depth, plus the current one.
    struct Piece {
        double a, b;
        int depth;
    };
    std::array<Piece, ImplicitSurface::kMaxDepth + 2> stack;
    int top = 0;
    stack[top++] = {clipped->min, clipped->max, 0};
    while (top > 0) {
        const Piece piece = stack[--top];
        if (search.segments >= surface.max_segments) {
            search.found = ImplicitSearch::Found::kExhausted;
            return search;
        }
        ++search.segments;

        const RealInterval t{piece.a, piece.b};
        const Expression::RaySegment e = root_search.f().along_ray(ray, t);
        RealInterval value = e.value;
        if (value.excludes_zero()) continue;  // also when f is undefined on all of the piece
        const double mid = 0.5 * (piece.a + piece.b);
        if (e.continuous) {
            // Mean value form f(m) + f'(T) (T - m) (Moore 1966): its overestimation shrinks
            // with the square of the width, the natural extension's only linearly. Both
            // enclose the range, so their intersection does too.
            const RealInterval at_mid = root_search.f().enclose_along_ray(ray, mid);
            value = intersect(value, at_mid + e.slope * (t - RealInterval::point(mid)));
            if (value.excludes_zero()) continue;
            if (e.slope.excludes_zero()) {
                if (const auto root = root_search.resolve_monotonic(piece.a, piece.b))
                    return report(*root, ImplicitSearch::Found::kSignChange);
                continue;
            }
        }
        const bool leaf = piece.b - piece.a <= root_search.tolerance() ||
                          piece.depth >= ImplicitSurface::kMaxDepth || !(mid > piece.a) ||
                          !(mid < piece.b);
        if (leaf) {
            ImplicitSearch::Found found{};
            if (const auto root = root_search.resolve_leaf(piece.a, piece.b, e.continuous, found))
                return report(*root, found);
            continue;
        }
        stack[top++] = {mid, piece.b, piece.depth + 1};
        stack[top++] = {piece.a, mid, piece.depth + 1};
    }
    return search;
}

std::optional<Point3> point_cut_open(const ImplicitSurface& surface) {
    if (!surface.f) return std::nullopt;
    const Expression& f = *surface.f;
    const Bounds3& box = surface.region;
    constexpr int kMaxLevel = 6;  // squares of 1/64 of the face's sides
    struct Square {
        double u0, u1, v0, v1;
        int level;
    };
    for (int axis = 0; axis < 3; ++axis) {
        // The face's own coordinates: the two other axes.
        const int a = (axis + 1) % 3, b = (axis + 2) % 3;
        for (const float fixed : {box.min[axis], box.max[axis]}) {
            const auto point_at = [&](double u, double v) {
                double p[3];
                p[axis] = fixed;
                p[a] = u;
                p[b] = v;
                return Point3(float(p[0]), float(p[1]), float(p[2]));
            };
            // Depth first, so the stack holds at most three squares per level.
            std::array<Square, 4 * (kMaxLevel + 1)> stack;
            int top = 0;
            stack[top++] = {box.min[a], box.max[a], box.min[b], box.max[b], 0};
            while (top > 0) {
                const Square q = stack[--top];
                RealInterval range[3];
                range[axis] = RealInterval::point(fixed);
                range[a] = {q.u0, q.u1};
                range[b] = {q.v0, q.v1};
                const RealInterval value = f.range(range[0], range[1], range[2]);
                if (value.is_empty() || value.lo >= 0) continue;  // no f < 0 in this square
                const Point3 centre = point_at(0.5 * (q.u0 + q.u1), 0.5 * (q.v0 + q.v1));
                if (f.value(centre) < 0) return centre;
                if (q.level == kMaxLevel) continue;
                const double um = 0.5 * (q.u0 + q.u1), vm = 0.5 * (q.v0 + q.v1);
                stack[top++] = {q.u0, um, q.v0, vm, q.level + 1};
                stack[top++] = {um, q.u1, q.v0, vm, q.level + 1};
                stack[top++] = {q.u0, um, vm, q.v1, q.level + 1};
                stack[top++] = {um, q.u1, vm, q.v1, q.level + 1};
            }
        }
    }
    return std::nullopt;
}

std::optional<ShapeHit> ImplicitSurface::intersect(const Ray& ray, Interval t_range) const {
    return find_first_root(*this, ray, t_range).hit;
}

SurfacePoint ImplicitSurface::surface_at(const Ray& ray, const ShapeHit& hit) const {
    SurfacePoint sp;
    sp.p = ray.at(hit.t);
    sp.error = tolerance;  // the root is bracketed to within the tolerance
    const Expression::Gradient g = f->gradient(sp.p.x, sp.p.y, sp.p.z);
    const double norm = std::sqrt(g.dx * g.dx + g.dy * g.dy + g.dz * g.dz);
    if (norm > 0 && std::isfinite(norm)) {
        sp.normal = Normal3(float(g.dx / norm), float(g.dy / norm), float(g.dz / norm));
        sp.normal = normalize(sp.normal);  // unit in float, not only in double
    } else {
        sp.normal = Normal3(-ray.direction);
    }
    sp.shading_normal = sp.normal;

    sp.uv = spherical_uv(sp.p, region.center());
    return sp;
}

std::string describe_problem(const ImplicitSurface& surface) {
    if (!surface.f) return "implicit surface needs a function";
    if (surface.region.is_empty() || !surface.region.is_finite())
        return "implicit surface bounds must be a finite, non-empty box";
    if (!(surface.tolerance > 0) || !std::isfinite(surface.tolerance))
        return "implicit surface tolerance must be > 0, got " + number_text(surface.tolerance);
    if (surface.max_segments < 1)
        return "implicit surface max_segments must be >= 1, got " +
               number_text(surface.max_segments);
    return {};
}

}  // namespace glint
