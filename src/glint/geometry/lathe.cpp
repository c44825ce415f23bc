// The lathe's pieces, oriented and grouped, and its ray test: a quadratic a piece.
#include "glint/geometry/lathe.h"

#include <algorithm>
#include <cmath>

#include "glint/math/constants.h"
#include "glint/math/quadratic.h"

namespace glint {

namespace {

Point2 unit_right_of(Point2 t) {
    const double len = std::hypot(double(t.x), double(t.y));
    if (!(len > 0)) return {0, 0};
    return {float(t.y / len), float(-t.x / len)};
}

bool finite(Point2 p) { return std::isfinite(p.x) && std::isfinite(p.y); }

// The t where the ray meets the surface of revolution of the piece, in [t_min, t_max], with the
// place s along the piece (0 at a, 1 at b); the nearest such.
struct PieceHit {
    double t, s;
};

std::optional<PieceHit> hit_piece(const LathePiece& piece, const double o[3], const double d[3],
                                  double t_min, double t_max) {
    const double r0 = piece.a.x, y0 = piece.a.y, r1 = piece.b.x, y1 = piece.b.y;
    std::optional<PieceHit> best;
    const auto keep = [&](double t, double s) {
        if (t >= t_min && t <= t_max && s >= 0 && s <= 1 && (!best || t < best->t))
            best = PieceHit{t, s};
    };
    if (y0 == y1) {
        // A ring across the axis: the plane y = y0, between the radii.
        if (d[1] == 0) return std::nullopt;
        const double t = (y0 - o[1]) / d[1];
        const double x = o[0] + t * d[0], z = o[2] + t * d[2];
        const double r = std::sqrt(x * x + z * z);
        const double lo = std::min(std::abs(r0), std::abs(r1)),
                     hi = std::max(std::abs(r0), std::abs(r1));
        if (r >= lo && r <= hi && hi > lo)
            keep(t, (r - std::abs(r0)) / (std::abs(r1) - std::abs(r0)));
        return best;
    }
    // r(y) = r0 + k (y - y0) along the piece; x^2 + z^2 - r(y)^2 = 0 is a quadratic in t.
    const double k = (r1 - r0) / (y1 - y0);
    const double c0 = r0 + k * (o[1] - y0), c1 = k * d[1];  // r(t) = c0 + c1 t
    const double a = d[0] * d[0] + d[2] * d[2] - c1 * c1;
    const double b = 2 * (o[0] * d[0] + o[2] * d[2] - c0 * c1);
    const double c = o[0] * o[0] + o[2] * o[2] - c0 * c0;
    double roots[2];
    int count = 0;
    if (a == 0) {
        if (b != 0) roots[count++] = -c / b;
    } else if (const auto solved = solve_quadratic_double(a, b, c)) {
        roots[count++] = solved->t0;
        roots[count++] = solved->t1;
    }
    for (int i = 0; i < count; ++i) {
        const double y = o[1] + roots[i] * d[1];
        keep(roots[i], (y - y0) / (y1 - y0));
    }
    return best;
}

}  // namespace

std::variant<Lathe, std::string> make_lathe(const Outline& open_curve) {
    if (open_curve.empty()) return std::string("lathe curve is empty");
    for (const OutlineEdge& e : open_curve) {
        if (!finite(e.a) || !finite(e.b) || !finite(e.tangent_a) || !finite(e.tangent_b))
            return std::string("lathe curve has a point that is not finite");
    }
    Lathe lathe;
    const Point2 start = open_curve.front().a, finish = open_curve.back().b;
    lathe.closed = open_curve.size() >= 2 &&
                   std::abs(start.x - finish.x) <= 1e-6f * (1 + std::abs(start.x)) &&
                   std::abs(start.y - finish.y) <= 1e-6f * (1 + std::abs(start.y));
    const Outline curve = joined(open_curve, lathe.closed);
    // Counter-clockwise in the (r, y) plane, the enclosed region is on the left: outward is to
    // the right. Measured with |r|, as the lathe turns r and -r alike.
    double twice_area = 0;
    for (const OutlineEdge& e : curve)
        twice_area += std::abs(e.a.x) * e.b.y - std::abs(e.b.x) * e.a.y;
    const float sign = !lathe.closed || twice_area > 0 ? 1.0f : -1.0f;
    auto profile = std::make_shared<LatheProfile>();
    for (std::size_t i = 0; i < curve.size(); ++i) {
        const OutlineEdge& e = curve[i];
        // A piece on the axis turns into nothing.
        if (e.a == e.b || (e.a.x == 0 && e.b.x == 0)) continue;
        const auto outward = [sign](Point2 t) {
            const Point2 r = unit_right_of(t);
            return Point2{sign * r.x, sign * r.y};
        };
        const Point2 face = outward({e.b.x - e.a.x, e.b.y - e.a.y});
        Point2 na = outward(e.tangent_a), nb = outward(e.tangent_b);
        if (na == Point2{0, 0}) na = face;
        if (nb == Point2{0, 0}) nb = face;
        profile->pieces.push_back({e.a, e.b, face, na, nb});
    }
    if (profile->pieces.empty()) return std::string("lathe curve has no length");
    profile->bottom = kInfinity;
    profile->top = -kInfinity;
    for (std::size_t begin = 0; begin < profile->pieces.size(); begin += kLatheGroup) {
        float radius = 0, bottom = kInfinity, top = -kInfinity;
        const std::size_t end = std::min(begin + kLatheGroup, profile->pieces.size());
        for (std::size_t k = begin; k < end; ++k) {
            for (const Point2 p : {profile->pieces[k].a, profile->pieces[k].b}) {
                radius = std::max(radius, std::abs(p.x));
                bottom = std::min(bottom, p.y);
                top = std::max(top, p.y);
            }
        }
        profile->group_radius.push_back(radius);
        profile->group_bottom.push_back(bottom);
        profile->group_top.push_back(top);
        profile->radius = std::max(profile->radius, radius);
        profile->bottom = std::min(profile->bottom, bottom);
        profile->top = std::max(profile->top, top);
    }
    lathe.profile = std::move(profile);
    return lathe;
}

Bounds3 Lathe::bounds() const {
    const float r = profile->radius;
    return {{-r, profile->bottom, -r}, {r, profile->top, r}};
}

std::optional<ShapeHit> Lathe::intersect(const Ray& ray, Interval t_range) const {
    const double o[3] = {ray.origin.x, ray.origin.y, ray.origin.z};
    const double d[3] = {ray.direction.x, ray.direction.y, ray.direction.z};
    // Where the ray runs within radius R of the axis: (ox + t dx)^2 + (oz + t dz)^2 <= R^2.
    const double a = d[0] * d[0] + d[2] * d[2], b = o[0] * d[0] + o[2] * d[2];
    const double c = o[0] * o[0] + o[2] * o[2];
    const auto near_axis = [&](double radius, double bottom, double top, double& t0, double& t1) {
        const double pad = 1e-6 * (1 + radius);
        const double r = radius + pad;
        if (a > 0) {
            const double disc = b * b - a * (c - r * r);
            if (disc < 0) return false;
            const double root = std::sqrt(disc);
            t0 = std::max(t0, (-b - root) / a);
            t1 = std::min(t1, (-b + root) / a);
        } else if (c > r * r) {
            return false;
        }
        if (d[1] != 0) {
            double y0 = (bottom - pad - o[1]) / d[1], y1 = (top + pad - o[1]) / d[1];
            if (y0 > y1) std::swap(y0, y1);
            t0 = std::max(t0, y0);
            t1 = std::min(t1, y1);
        } else if (o[1] < bottom - pad || o[1] > top + pad) {
            return false;
        }
        return t0 <= t1;
    };
    double all0 = t_range.min, all1 = t_range.max;
    if (!near_axis(profile->radius, profile->bottom, profile->top, all0, all1)) return std::nullopt;
    // The pieces are solved from where the ray enters the lathe's cylinder, so that their
    // coefficients are of the lathe's size however far away the ray starts.
    const double base = all0;
    const double moved[3] = {o[0] + base * d[0], o[1] + base * d[1], o[2] + base * d[2]};
    double best = t_range.max;
    std::optional<ShapeHit> hit;
    const std::size_t groups = profile->group_radius.size();
    for (std::size_t g = 0; g < groups; ++g) {
        double t0 = t_range.min, t1 = best;
        if (!near_axis(profile->group_radius[g], profile->group_bottom[g], profile->group_top[g],
                       t0, t1))
            continue;
        const std::size_t begin = g * kLatheGroup;
        const std::size_t end = std::min(begin + kLatheGroup, profile->pieces.size());
        for (std::size_t k = begin; k < end; ++k) {
            const auto h = hit_piece(profile->pieces[k], moved, d, t_range.min - base, best - base);
            if (!h) continue;
            best = base + h->t;
            hit = ShapeHit{float(best), float(h->s), 0, std::uint32_t(k)};
        }
    }
    return hit;
}

SurfacePoint Lathe::surface_at(const Ray& ray, const ShapeHit& hit) const {
    const LathePiece& piece = profile->pieces[hit.part];
    const float s = std::clamp(hit.u, 0.0f, 1.0f);
    SurfacePoint sp;
    sp.p = ray.at(hit.t);
    const float r = std::hypot(sp.p.x, sp.p.z);
    // The radial direction, and which way r counts along it: a piece at negative r turns the
    // same surface with its normal's r part reversed.
    const float r_piece = piece.a.x + s * (piece.b.x - piece.a.x);
    const float side = r_piece < 0 ? -1.0f : 1.0f;
    const Vector3 radial = r > 0 ? Vector3{sp.p.x / r, 0, sp.p.z / r} : Vector3{1, 0, 0};
    const auto to_3d = [&](Point2 n) {
        const Vector3 v = radial * (side * n.x) + Vector3{0, n.y, 0};
        const float len = length(v);
        return len > 0 ? Normal3(v / len) : Normal3{0, 1, 0};
    };
    sp.normal = to_3d(piece.normal);
    sp.shading_normal = to_3d({piece.normal_a.x + s * (piece.normal_b.x - piece.normal_a.x),
                               piece.normal_a.y + s * (piece.normal_b.y - piece.normal_a.y)});
    if (dot(to_vector(sp.shading_normal), to_vector(sp.normal)) < 0) sp.shading_normal = sp.normal;
    const float angle = std::atan2(-sp.p.z, sp.p.x);
    sp.uv = {angle < 0 ? angle / (2 * kPi) + 1 : angle / (2 * kPi),
             (float(hit.part) + s) / float(profile->pieces.size())};
    return sp;
}

}  // namespace glint
