// POV-Ray's prism splines, segment by segment in power form, as POV-Ray walks them.
#include "glint/geometry/spline_outlines.h"

#include <algorithm>
#include <cmath>

namespace glint {

namespace {

bool same_point(Point2 a, Point2 b) {
    return std::abs(a.x - b.x) < 1e-10 && std::abs(a.y - b.y) < 1e-10;
}

// The power-form curve of segment i of the spline (POV-Ray's blending of the points).
CubicCurve segment(SplineKind kind, std::span<const Point2> p, std::size_t i) {
    const auto blend = [&](float w0, float w1, float w2, float w3) {
        const auto at = [&](std::size_t k) {
            return k < p.size() ? p[k] : Point2{};  // unused weights are 0
        };
        const Point2 a = at(i), b = at(i + 1), c = at(i + 2), d = at(i + 3);
        return Point2{w0 * a.x + w1 * b.x + w2 * c.x + w3 * d.x,
                      w0 * a.y + w1 * b.y + w2 * c.y + w3 * d.y};
    };
    switch (kind) {
        case SplineKind::linear:
            return {{}, {}, blend(-1, 1, 0, 0), blend(1, 0, 0, 0)};
        case SplineKind::quadratic:
            return {{}, blend(0.5f, -1, 0.5f, 0), blend(-0.5f, 0, 0.5f, 0), blend(0, 1, 0, 0)};
        case SplineKind::cubic:
            return {blend(-0.5f, 1.5f, -1.5f, 0.5f), blend(1, -2.5f, 2, -0.5f),
                    blend(-0.5f, 0, 0.5f, 0), blend(0, 1, 0, 0)};
        case SplineKind::bezier:
            return {blend(-1, 3, -3, 1), blend(3, -6, 3, 0), blend(-3, 3, 0, 0), blend(1, 0, 0, 0)};
    }
    return {};
}

const char* spline_name(SplineKind kind) {
    return kind == SplineKind::linear      ? "linear"
           : kind == SplineKind::quadratic ? "quadratic"
           : kind == SplineKind::cubic     ? "cubic"
                                           : "bezier";
}

// The diagonal of the points' box (at least a tiny length): what curve tolerances scale with.
double extent_of(std::span<const Point2> points) {
    Point2 lo = points[0], hi = points[0];
    for (const Point2 p : points) {
        lo = {std::min(lo.x, p.x), std::min(lo.y, p.y)};
        hi = {std::max(hi.x, p.x), std::max(hi.y, p.y)};
    }
    return std::max(double(std::hypot(hi.x - lo.x, hi.y - lo.y)), 1e-30);
}

// How many points past i a segment reads, and how many it steps over when it closes an outline.
std::size_t reach(SplineKind kind) {
    return kind == SplineKind::linear ? 1 : kind == SplineKind::quadratic ? 2 : 3;
}

}  // namespace

std::optional<SplineKind> spline_kind(std::string_view name) {
    if (name == "linear") return SplineKind::linear;
    if (name == "quadratic") return SplineKind::quadratic;
    if (name == "cubic") return SplineKind::cubic;
    if (name == "bezier") return SplineKind::bezier;
    return std::nullopt;
}

std::variant<Outline, std::string> spline_curve(SplineKind kind, std::span<const Point2> points) {
    const std::size_t n = points.size();
    const std::size_t least = kind == SplineKind::linear      ? 2
                              : kind == SplineKind::quadratic ? 3
                                                              : 4;
    if (n < least)
        return "a " + std::string(spline_name(kind)) + " spline needs at least " +
               std::to_string(least) + " points, got " + std::to_string(n);
    if (kind == SplineKind::bezier && n % 4 != 0)
        return "a bezier spline takes four points a curve: " + std::to_string(n) +
               " points are not a multiple of 4";
    const double tolerance = 1e-4 * extent_of(points);
    Outline curve;
    if (kind == SplineKind::linear) {
        for (std::size_t i = 0; i + 1 < n; ++i) append_line(curve, points[i], points[i + 1]);
    } else {
        const std::size_t step = kind == SplineKind::bezier ? 4 : 1;
        for (std::size_t i = 0; i + reach(kind) < n; i += step)
            append_curve(curve, segment(kind, points, i), tolerance);
    }
    if (curve.empty()) return std::string("the spline's points all coincide");
    return curve;
}

std::variant<Outline, std::string> sor_curve(std::span<const Point2> p, bool open) {
    const std::size_t n = p.size();
    if (n < 4) return "a sor needs at least 4 points, got " + std::to_string(n);
    // The curve runs up from the second point to the next-to-last; the slopes take the heights
    // of the points either side, which must differ.
    for (std::size_t i = 1; i + 1 < n; ++i) {
        const bool rises = i + 2 < n ? p[i + 1].y > p[i].y : true;
        if (!rises || !(p[i + 1].y != p[i - 1].y))
            return "heights must rise along the curve: point " + std::to_string(i + 2) +
                   " is not above point " + std::to_string(i + 1);
    }
    Outline curve;
    const auto point_on = [](double r2, double y) {
        return Point2{float(std::sqrt(std::max(r2, 0.0))), float(y)};
    };
    double bottom_r2 = 0, top_r2 = 0;
    for (std::size_t i = 0; i + 3 < n; ++i) {
        // Hermite form of r^2(y) on [y1, y2]: values q1, q2 and slopes m1, m2 there.
        const double y1 = p[i + 1].y, y2 = p[i + 2].y, h = y2 - y1;
        const double q1 = double(p[i + 1].x) * p[i + 1].x, q2 = double(p[i + 2].x) * p[i + 2].x;
        const double m1 =
            2.0 * p[i + 1].x * (double(p[i + 2].x) - p[i].x) / (double(p[i + 2].y) - p[i].y);
        const double m2 = 2.0 * p[i + 2].x * (double(p[i + 3].x) - p[i + 1].x) /
                          (double(p[i + 3].y) - p[i + 1].y);
        const auto r2_at = [&](double s) {
            const double s2 = s * s, s3 = s2 * s;
            return (2 * s3 - 3 * s2 + 1) * q1 + (s3 - 2 * s2 + s) * h * m1 +
                   (-2 * s3 + 3 * s2) * q2 + (s3 - s2) * h * m2;
        };
        const auto slope_at = [&](double s) {  // d(r^2)/dy
            const double s2 = s * s;
            return ((6 * s2 - 6 * s) * q1 + (3 * s2 - 4 * s + 1) * h * m1 + (-6 * s2 + 6 * s) * q2 +
                    (3 * s2 - 2 * s) * h * m2) /
                   h;
        };
        // The way the curve runs, (dr/dy, 1) scaled by 2r: finite where r is 0.
        const auto tangent_at = [&](double s) {
            return Point2{float(slope_at(s)), float(2 * std::sqrt(std::max(r2_at(s), 0.0)))};
        };
        if (i == 0) bottom_r2 = r2_at(0);
        top_r2 = r2_at(1);
        constexpr int kSteps = 32;
        for (int k = 0; k < kSteps; ++k) {
            const double s0 = double(k) / kSteps, s1 = double(k + 1) / kSteps;
            const Point2 a = point_on(r2_at(s0), y1 + s0 * h), b = point_on(r2_at(s1), y1 + s1 * h);
            if (!(a == b)) curve.push_back({a, b, tangent_at(s0), tangent_at(s1)});
        }
    }
    if (curve.empty()) return std::string("the sor's curve has no length");
    if (!open) {
        // The caps: from the axis out to the curve's start, and from its end back to the axis.
        const float y_bottom = p[1].y, y_top = p[n - 2].y;
        Outline closed;
        append_line(closed, {0, y_bottom}, point_on(bottom_r2, y_bottom));
        closed.insert(closed.end(), curve.begin(), curve.end());
        append_line(closed, point_on(top_r2, y_top), {0, y_top});
        append_line(closed, {0, y_top}, {0, y_bottom});
        return closed;
    }
    return curve;
}

std::variant<SplineOutlines, std::string> spline_outlines(SplineKind kind,
                                                          std::span<const Point2> points) {
    const std::size_t n = points.size();
    const std::size_t least = kind == SplineKind::linear ? 3 : 4;
    if (n < least) {
        return "a " + std::string(spline_name(kind)) + " spline needs at least " +
               std::to_string(least) + " points, got " + std::to_string(n);
    }
    const double tolerance = 1e-4 * extent_of(points);

    SplineOutlines result;
    Outline outline;
    const auto start_of = [&](std::size_t i) {
        return kind == SplineKind::quadratic || kind == SplineKind::cubic ? i + 1 : i;
    };
    Point2 first = points[start_of(0)];
    const auto close = [&](bool by_line) {
        if (outline.empty()) return;
        if (by_line) {
            append_line(outline, outline.back().b, outline.front().a);
            ++result.closed_by_line;
        }
        result.outlines.push_back(std::move(outline));
        outline.clear();
    };
    for (std::size_t i = 0; i + 1 < n; ++i) {
        if (i + reach(kind) >= n) {
            return "too few points: the spline's segment from point " + std::to_string(i + 1) +
                   " needs point " + std::to_string(i + reach(kind) + 1) + ", but there are " +
                   std::to_string(n);
        }
        if (kind == SplineKind::linear) {
            append_line(outline, points[i], points[i + 1]);
        } else {
            append_curve(outline, segment(kind, points, i), tolerance);
        }
        // The point the segment ends on, and whether it closes the outline.
        const std::size_t end = kind == SplineKind::linear   ? i + 1
                                : kind == SplineKind::bezier ? i + 3
                                                             : i + 2;
        if (kind == SplineKind::bezier) {
            i += 3;
            if (same_point(points[end], first)) {
                close(false);
                if (i + 1 < n) first = points[i + 1];
            }
        } else if (same_point(points[end], first)) {
            close(false);
            i += reach(kind);
            if (start_of(i + 1) < n) first = points[start_of(i + 1)];
        }
    }
    close(true);
    return result;
}

}  // namespace glint
