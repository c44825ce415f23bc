// The prism's outlines turned into oriented, grouped edges, and its ray test: two caps and the
// walls, each wall a ray-segment test on the x-z plane.
#include "glint/geometry/prism.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace glint {

namespace {

struct Vec2 {
    double x = 0, y = 0;
};
Vec2 operator-(Vec2 a, Vec2 b) { return {a.x - b.x, a.y - b.y}; }
double cross(Vec2 a, Vec2 b) { return a.x * b.y - a.y * b.x; }
Vec2 to_vec(Point2 p) { return {p.x, p.y}; }

// The unit vector to the right of t (x-z plane seen with x right and z up), or (0, 0).
Point2 right_of(Point2 t) {
    const double len = std::hypot(double(t.x), double(t.y));
    if (!(len > 0)) return {0, 0};
    return {float(t.y / len), float(-t.x / len)};
}

double signed_area(const Outline& outline) {
    double twice = 0;
    for (const OutlineEdge& e : outline) twice += cross(to_vec(e.a), to_vec(e.b));
    return twice / 2;
}

// The even-odd crossing count of a ray from (x, z) towards +x over the edges [begin, end).
template <class Edge>
int crossings(const Edge* begin, const Edge* end, double x, double z) {
    int count = 0;
    for (const Edge* e = begin; e != end; ++e) {
        const double ay = e->a.y, by = e->b.y;
        if ((ay > z) == (by > z)) continue;
        const double at = e->a.x + (z - ay) / (by - ay) * (double(e->b.x) - e->a.x);
        if (at > x) ++count;
    }
    return count;
}

bool finite(Point2 p) { return std::isfinite(p.x) && std::isfinite(p.y); }

}  // namespace

Outline joined(Outline outline, bool closed) {
    const std::size_t joints =
        closed ? outline.size() : std::max<std::size_t>(outline.size(), 1) - 1;
    for (std::size_t i = 0; i < joints; ++i) {
        OutlineEdge& e = outline[i];
        const Point2 next = outline[(i + 1) % outline.size()].a;
        const float near = 1e-5f * std::max({1.0f, std::abs(next.x), std::abs(next.y)});
        if (std::abs(e.b.x - next.x) <= near && std::abs(e.b.y - next.y) <= near) e.b = next;
    }
    return outline;
}

void append_line(Outline& outline, Point2 a, Point2 b) {
    if (a == b) return;
    const Point2 t{b.x - a.x, b.y - a.y};
    outline.push_back({a, b, t, t});
}

void append_curve(Outline& outline, const CubicCurve& curve, double tolerance) {
    const Point2 A = curve.a, B = curve.b, C = curve.c, D = curve.d;
    const auto at = [&](double s) {
        return Point2{float(((A.x * s + B.x) * s + C.x) * s + D.x),
                      float(((A.y * s + B.y) * s + C.y) * s + D.y)};
    };
    const auto tangent = [&](double s) {
        return Point2{float((3 * A.x * s + 2 * B.x) * s + C.x),
                      float((3 * A.y * s + 2 * B.y) * s + C.y)};
    };
    const double bend =
        6 * std::hypot(double(A.x), double(A.y)) + 2 * std::hypot(double(B.x), double(B.y));
    const double wanted = std::ceil(std::sqrt(bend / (8 * std::max(tolerance, 1e-12))));
    const int steps = int(std::clamp(std::isfinite(wanted) ? wanted : 1.0, 1.0, 64.0));
    Point2 from = at(0), from_tangent = tangent(0);
    for (int i = 1; i <= steps; ++i) {
        const double s = double(i) / steps;
        const Point2 to = at(s), to_tangent = tangent(s);
        if (!(to == from)) outline.push_back({from, to, from_tangent, to_tangent});
        from = to;
        from_tangent = to_tangent;
    }
}

bool inside_profile(const PrismProfile& profile, double x, double z) {
    int count = 0;
    const std::size_t groups = profile.group_min.size();
    for (std::size_t g = 0; g < groups; ++g) {
        if (!(profile.group_min[g].y <= z && z <= profile.group_max[g].y &&
              x < profile.group_max[g].x))
            continue;
        const std::size_t begin = g * kPrismGroup;
        const std::size_t end = std::min(begin + kPrismGroup, profile.edges.size());
        count += crossings(profile.edges.data() + begin, profile.edges.data() + end, x, z);
    }
    return count % 2 == 1;
}

std::variant<Prism, std::string> make_prism(const std::vector<Outline>& outlines, float bottom,
                                            float top, bool open) {
    if (!(std::isfinite(bottom) && std::isfinite(top)) || !(bottom < top)) {
        std::ostringstream out;
        out << "prism heights must be finite with bottom < top, got " << bottom << " and " << top;
        return out.str();
    }
    auto profile = std::make_shared<PrismProfile>();
    double total_area = 0;
    for (std::size_t i = 0; i < outlines.size(); ++i) {
        for (const OutlineEdge& e : outlines[i]) {
            if (!finite(e.a) || !finite(e.b) || !finite(e.tangent_a) || !finite(e.tangent_b))
                return "prism outline " + std::to_string(i + 1) + " has a point that is not finite";
        }
        const Outline outline = joined(outlines[i], /*closed=*/true);
        const double area = signed_area(outline);
        if (outline.size() < 2 || area == 0) continue;  // no region: no wall either
        total_area += std::abs(area);
        // How many of the other outlines hold this one: its inside is solid where that is even.
        int depth = 0;
        for (std::size_t j = 0; j < outlines.size(); ++j) {
            if (j == i) continue;
            const Outline& other = outlines[j];
            depth += crossings(other.data(), other.data() + other.size(), outline[0].a.x,
                               outline[0].a.y) %
                     2;
        }
        // Counter-clockwise (area > 0), the inside is on the left; outward is then to the right.
        const float sign = (area > 0) == (depth % 2 == 0) ? 1.0f : -1.0f;
        const auto outward = [sign](Point2 t) {
            const Point2 r = right_of(t);
            return Point2{sign * r.x, sign * r.y};
        };
        for (const OutlineEdge& e : outline) {
            const Point2 face = outward({e.b.x - e.a.x, e.b.y - e.a.y});
            Point2 na = outward(e.tangent_a), nb = outward(e.tangent_b);
            if (na == Point2{0, 0}) na = face;
            if (nb == Point2{0, 0}) nb = face;
            profile->edges.push_back({e.a, e.b, face, na, nb});
        }
    }
    if (!(total_area > 0) || !std::isfinite(total_area)) {
        return std::string("prism outlines enclose no area");
    }
    constexpr float inf = std::numeric_limits<float>::infinity();
    profile->min = {inf, inf};
    profile->max = {-inf, -inf};
    for (std::size_t begin = 0; begin < profile->edges.size(); begin += kPrismGroup) {
        Point2 lo{inf, inf}, hi{-inf, -inf};
        const std::size_t end = std::min(begin + kPrismGroup, profile->edges.size());
        for (std::size_t k = begin; k < end; ++k) {
            for (const Point2 p : {profile->edges[k].a, profile->edges[k].b}) {
                lo = {std::min(lo.x, p.x), std::min(lo.y, p.y)};
                hi = {std::max(hi.x, p.x), std::max(hi.y, p.y)};
            }
        }
        profile->group_min.push_back(lo);
        profile->group_max.push_back(hi);
        profile->min = {std::min(profile->min.x, lo.x), std::min(profile->min.y, lo.y)};
        profile->max = {std::max(profile->max.x, hi.x), std::max(profile->max.y, hi.y)};
    }
    Prism prism;
    prism.profile = std::move(profile);
    prism.bottom = bottom;
    prism.top = top;
    prism.open = open;
    return prism;
}

Bounds3 Prism::bounds() const {
    return {{profile->min.x, bottom, profile->min.y}, {profile->max.x, top, profile->max.y}};
}

namespace {

// The parameter range [t0, t1] of the 2D ray o + t d inside the box [lo, hi]; empty when
// t0 > t1. A zero direction component keeps the range when o lies within that slab.
bool clip_to_box(Vec2 o, Vec2 d, Point2 lo, Point2 hi, double& t0, double& t1) {
    const double os[2] = {o.x, o.y}, ds[2] = {d.x, d.y};
    const double los[2] = {lo.x, lo.y}, his[2] = {hi.x, hi.y};
    for (int k = 0; k < 2; ++k) {
        if (ds[k] == 0) {
            if (os[k] < los[k] || os[k] > his[k]) return false;
            continue;
        }
        double a = (los[k] - os[k]) / ds[k], b = (his[k] - os[k]) / ds[k];
        if (a > b) std::swap(a, b);
        t0 = std::max(t0, a);
        t1 = std::min(t1, b);
    }
    return t0 <= t1;
}

}  // namespace

std::optional<ShapeHit> Prism::intersect(const Ray& ray, Interval t_range) const {
    const double ox = ray.origin.x, oy = ray.origin.y, oz = ray.origin.z;
    const double dx = ray.direction.x, dy = ray.direction.y, dz = ray.direction.z;
    double best = t_range.max;
    std::optional<ShapeHit> hit;
    if (!open && dy != 0) {
        for (std::uint32_t cap = 0; cap < 2; ++cap) {
            const double t = ((cap == 0 ? bottom : top) - oy) / dy;
            if (!(t >= t_range.min && t <= best)) continue;
            if (inside_profile(*profile, ox + t * dx, oz + t * dz)) {
                best = t;
                hit = ShapeHit{float(t), 0, 0, cap};
            }
        }
    }
    // The walls: where the ray is between the heights, and the 2D ray meets an edge.
    double t0 = t_range.min, t1 = best;
    if (dy == 0) {
        if (oy < bottom || oy > top) return hit;
    } else {
        double a = (bottom - oy) / dy, b = (top - oy) / dy;
        if (a > b) std::swap(a, b);
        t0 = std::max(t0, a);
        t1 = std::min(t1, b);
    }
    const Vec2 o{ox, oz}, d{dx, dz};
    if (!(t0 <= t1) || (d.x == 0 && d.y == 0)) return hit;
    if (double c0 = t0, c1 = t1; !clip_to_box(o, d, profile->min, profile->max, c0, c1)) return hit;
    const std::size_t groups = profile->group_min.size();
    for (std::size_t g = 0; g < groups; ++g) {
        double g0 = t0, g1 = std::min(t1, best);
        if (!clip_to_box(o, d, profile->group_min[g], profile->group_max[g], g0, g1)) continue;
        const std::size_t begin = g * kPrismGroup;
        const std::size_t end = std::min(begin + kPrismGroup, profile->edges.size());
        for (std::size_t k = begin; k < end; ++k) {
            const PrismEdge& e = profile->edges[k];
            const Vec2 a = to_vec(e.a), along = to_vec(e.b) - a;
            const double denom = cross(d, along);
            if (denom == 0) continue;  // parallel: the wall is seen edge-on
            const Vec2 w = a - o;
            const double t = cross(w, along) / denom, s = cross(w, d) / denom;
            if (!(s >= 0 && s <= 1 && t >= t0 && t <= t1 && t <= best)) continue;
            best = t;
            hit = ShapeHit{float(t), float(s), 0, std::uint32_t(2 + k)};
        }
    }
    return hit;
}

SurfacePoint Prism::surface_at(const Ray& ray, const ShapeHit& hit) const {
    SurfacePoint sp;
    sp.p = ray.at(hit.t);
    if (hit.part < 2) {
        sp.p.y = hit.part == 0 ? bottom : top;  // snap onto the cap
        sp.normal = sp.shading_normal = {0, hit.part == 0 ? -1.0f : 1.0f, 0};
        sp.uv = {sp.p.x, sp.p.z};
        return sp;
    }
    const PrismEdge& e = profile->edges[hit.part - 2];
    const float s = std::clamp(hit.u, 0.0f, 1.0f);
    sp.normal = {e.normal.x, 0, e.normal.y};
    const Point2 n{e.normal_a.x + s * (e.normal_b.x - e.normal_a.x),
                   e.normal_a.y + s * (e.normal_b.y - e.normal_a.y)};
    const float len = std::hypot(n.x, n.y);
    sp.shading_normal = len > 0 ? Normal3{n.x / len, 0, n.y / len} : sp.normal;
    sp.uv = {s, std::clamp((sp.p.y - bottom) / (top - bottom), 0.0f, 1.0f)};
    return sp;
}

}  // namespace glint
