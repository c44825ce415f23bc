// Affine maps in doubles, and the set operations of Clipper with non-zero filling.
#include "glint/render/beam/planar_region.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace glint::beam {

Vector3d Affine::linear(Vector3d v) const {
    return {m[0][0] * v.x + m[0][1] * v.y + m[0][2] * v.z,
            m[1][0] * v.x + m[1][1] * v.y + m[1][2] * v.z,
            m[2][0] * v.x + m[2][1] * v.y + m[2][2] * v.z};
}

Vector3d Affine::linear_transposed(Vector3d v) const {
    return {m[0][0] * v.x + m[1][0] * v.y + m[2][0] * v.z,
            m[0][1] * v.x + m[1][1] * v.y + m[2][1] * v.z,
            m[0][2] * v.x + m[1][2] * v.y + m[2][2] * v.z};
}

Affine Affine::after(const Affine& inner) const {
    Affine r;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            r.m[i][j] = m[i][0] * inner.m[0][j] + m[i][1] * inner.m[1][j] + m[i][2] * inner.m[2][j];
    r.t = apply(inner.t);
    return r;
}

Affine Affine::inverse() const {
    // The adjugate over the determinant; mirrors and apparent-depth maps are far from singular.
    const double(&a)[3][3] = m;
    Affine r;
    r.m[0][0] = a[1][1] * a[2][2] - a[1][2] * a[2][1];
    r.m[0][1] = a[0][2] * a[2][1] - a[0][1] * a[2][2];
    r.m[0][2] = a[0][1] * a[1][2] - a[0][2] * a[1][1];
    r.m[1][0] = a[1][2] * a[2][0] - a[1][0] * a[2][2];
    r.m[1][1] = a[0][0] * a[2][2] - a[0][2] * a[2][0];
    r.m[1][2] = a[0][2] * a[1][0] - a[0][0] * a[1][2];
    r.m[2][0] = a[1][0] * a[2][1] - a[1][1] * a[2][0];
    r.m[2][1] = a[0][1] * a[2][0] - a[0][0] * a[2][1];
    r.m[2][2] = a[0][0] * a[1][1] - a[0][1] * a[1][0];
    const double det = a[0][0] * r.m[0][0] + a[0][1] * r.m[1][0] + a[0][2] * r.m[2][0];
    for (auto& row : r.m)
        for (double& x : row) x /= det;
    r.t = r.linear(t) * -1.0;
    return r;
}

PlaneD Affine::pull_back(const PlaneD& plane) const {
    // dot(n, m x + t) = d  <=>  dot(m^T n, x) = d - dot(n, t)
    return {linear_transposed(plane.n), plane.d - dot(plane.n, t)};
}

Affine mirror_in(const PlaneD& plane) { return scale_across(plane, -1); }

Affine scale_across(const PlaneD& plane, double factor) {
    // x + (factor - 1) at(x) n: the linear part I + (factor - 1) n n^T, the plane held still.
    const Vector3d n = plane.n;
    const double k = factor - 1;
    const double c[3] = {n.x, n.y, n.z};
    Affine a;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) a.m[i][j] = (i == j ? 1 : 0) + k * c[i] * c[j];
    a.t = n * (-k * plane.d);
    return a;
}

Vector3d PlaneFrame::world(const IntPoint& p) const {
    return origin + (u * double(p.X) + v * double(p.Y)) * (1 / scale);
}

IntPoint PlaneFrame::local(Vector3d p) const {
    const Vector3d d = p - origin;
    return {ClipperLib::cInt(std::llround(dot(d, u) * scale)),
            ClipperLib::cInt(std::llround(dot(d, v) * scale))};
}

PlaneFrame frame_of_plane(Vector3d origin, Vector3d n, double scale) {
    // Any unit u in the plane: across the normal's smallest component.
    const Vector3d axis =
        std::abs(n.x) < std::abs(n.y)
            ? (std::abs(n.x) < std::abs(n.z) ? Vector3d{1, 0, 0} : Vector3d{0, 0, 1})
            : (std::abs(n.y) < std::abs(n.z) ? Vector3d{0, 1, 0} : Vector3d{0, 0, 1});
    Vector3d u = cross(n, axis);
    u = u * (1 / std::sqrt(dot(u, u)));
    return {origin, u, cross(n, u), n, scale};
}

Side side_of(const PlaneFrame& frame, const Paths& region, const PlaneD& plane, double tolerance) {
    bool front = false, back = false;
    for (const Path& path : region)
        for (const IntPoint& p : path) {
            const double s = plane.at(frame.world(p));
            front |= s > tolerance;
            back |= s < -tolerance;
        }
    if (front && back) return Side::straddles;
    if (front) return Side::front;
    if (back) return Side::back;
    return Side::in_plane;
}

Paths clip_to_halfspace(const PlaneFrame& frame, const Paths& region, const PlaneD& plane) {
    // In the frame's integers the half-space is the half-plane a X + b Y + c >= 0. Clip the
    // region's bounding box to it (Sutherland-Hodgman on four corners), then intersect.
    const double a = dot(plane.n, frame.u) / frame.scale, b = dot(plane.n, frame.v) / frame.scale,
                 c = plane.at(frame.origin);
    bool inside = false, outside = false;
    for (const Path& path : region)
        for (const IntPoint& p : path) {
            const double s = a * double(p.X) + b * double(p.Y) + c;
            (s >= 0 ? inside : outside) = true;
        }
    if (!outside) return region;
    if (!inside) return {};
    const ClipperLib::IntRect box = bounds_of(region);
    const double x0 = double(box.left) - 2, x1 = double(box.right) + 2;
    const double y0 = double(box.top) - 2, y1 = double(box.bottom) + 2;
    const double corners[4][2] = {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
    Path kept;
    for (int i = 0; i < 4; ++i) {
        const double* p = corners[i];
        const double* q = corners[(i + 1) % 4];
        const double sp = a * p[0] + b * p[1] + c, sq = a * q[0] + b * q[1] + c;
        if (sp >= 0)
            kept.push_back(
                {ClipperLib::cInt(std::llround(p[0])), ClipperLib::cInt(std::llround(p[1]))});
        if ((sp >= 0) != (sq >= 0)) {
            const double f = sp / (sp - sq);
            kept.push_back({ClipperLib::cInt(std::llround(p[0] + f * (q[0] - p[0]))),
                            ClipperLib::cInt(std::llround(p[1] + f * (q[1] - p[1])))});
        }
    }
    if (kept.size() < 3) return {};
    return intersection(region, {kept});
}

namespace {

Paths execute(ClipperLib::ClipType type, const Paths& a, const Paths* b,
              ClipperLib::PolyFillType fill = ClipperLib::pftNonZero) {
    ClipperLib::Clipper clipper;
    clipper.AddPaths(a, ClipperLib::ptSubject, true);
    if (b) clipper.AddPaths(*b, ClipperLib::ptClip, true);
    Paths result;
    clipper.Execute(type, result, fill, ClipperLib::pftNonZero);
    return result;
}

}  // namespace

Paths intersection(const Paths& a, const Paths& b) {
    if (a.empty() || b.empty() || !overlap(bounds_of(a), bounds_of(b))) return {};
    return execute(ClipperLib::ctIntersection, a, &b);
}

Paths difference(const Paths& a, const Paths& b) {
    if (a.empty() || b.empty() || !overlap(bounds_of(a), bounds_of(b))) return a;
    return execute(ClipperLib::ctDifference, a, &b);
}

Paths union_of(const Paths& a) {
    if (a.empty()) return {};
    return execute(ClipperLib::ctUnion, a, nullptr);
}

Paths simplified(const Paths& outline, bool even_odd) {
    return execute(ClipperLib::ctUnion, outline, nullptr,
                   even_odd ? ClipperLib::pftEvenOdd : ClipperLib::pftNonZero);
}

void orient_positive(Paths& region) {
    double area = 0;
    for (const Path& ring : region) area += ClipperLib::Area(ring);
    if (area < 0)
        for (Path& ring : region) ClipperLib::ReversePath(ring);
}

ClipperLib::IntRect bounds_of(const Paths& region) {
    constexpr auto lo = std::numeric_limits<ClipperLib::cInt>::lowest();
    constexpr auto hi = std::numeric_limits<ClipperLib::cInt>::max();
    ClipperLib::IntRect r{hi, hi, lo, lo};
    for (const Path& path : region)
        for (const IntPoint& p : path) {
            r.left = std::min(r.left, p.X), r.right = std::max(r.right, p.X);
            r.top = std::min(r.top, p.Y), r.bottom = std::max(r.bottom, p.Y);
        }
    return r;
}

bool overlap(const ClipperLib::IntRect& a, const ClipperLib::IntRect& b) {
    return a.left <= b.right && b.left <= a.right && a.top <= b.bottom && b.top <= a.bottom;
}

}  // namespace glint::beam
