// The chain of spheres and tangent cones of a sphere sweep.
#include "glint/geometry/sphere_sweep.h"

#include <algorithm>
#include <cmath>

namespace glint {

namespace {

// The cubic splines' bases as POV-Ray writes them: row k holds the weights of the four spheres
// in the coefficient of t^k.
constexpr float kBSpline[4][4] = {{1.f / 6, 4.f / 6, 1.f / 6, 0},
                                  {-3.f / 6, 0, 3.f / 6, 0},
                                  {3.f / 6, -6.f / 6, 3.f / 6, 0},
                                  {-1.f / 6, 3.f / 6, -3.f / 6, 1.f / 6}};
constexpr float kCatmullRom[4][4] = {
    {0, 1, 0, 0}, {-0.5f, 0, 0.5f, 0}, {1, -2.5f, 2, -0.5f}, {-0.5f, 1.5f, -1.5f, 0.5f}};

// Cut [t0, t1] of the segment until the curve's midpoint lies within `allowed` of the chord's,
// adding each piece's end point.
void cut(SweepSpline spline, const std::vector<SweptSphere>& spheres, std::size_t segment, float t0,
         float t1, const SweptSphere& a, const SweptSphere& b, float tolerance, int depth,
         std::vector<SweptSphere>& chain) {
    const float tm = (t0 + t1) / 2;
    const SweptSphere m = sweep_at(spline, spheres, segment, tm);
    const Point3 chord_mid = a.center + (b.center - a.center) * 0.5f;
    const float stray =
        length(m.center - chord_mid) + std::abs(m.radius - (a.radius + b.radius) / 2);
    if (depth >= 8 || stray <= tolerance * std::min(a.radius, b.radius)) {
        chain.push_back(b);
        return;
    }
    cut(spline, spheres, segment, t0, tm, a, m, tolerance, depth + 1, chain);
    cut(spline, spheres, segment, tm, t1, m, b, tolerance, depth + 1, chain);
}

}  // namespace

SweptSphere sweep_at(SweepSpline spline, const std::vector<SweptSphere>& spheres,
                     std::size_t segment, float t) {
    if (spline == SweepSpline::linear) {
        const SweptSphere& a = spheres[segment];
        const SweptSphere& b = spheres[segment + 1];
        return {a.center + (b.center - a.center) * t, a.radius + (b.radius - a.radius) * t};
    }
    const auto& basis = spline == SweepSpline::b_spline ? kBSpline : kCatmullRom;
    const float powers[4] = {1, t, t * t, t * t * t};
    Vector3 center{0, 0, 0};
    float radius = 0;
    for (int i = 0; i < 4; ++i) {
        float weight = 0;
        for (int k = 0; k < 4; ++k) weight += powers[k] * basis[k][i];
        const SweptSphere& s = spheres[segment + std::size_t(i)];
        center += Vector3(s.center.x, s.center.y, s.center.z) * weight;
        radius += s.radius * weight;
    }
    return {Point3{center.x, center.y, center.z}, radius};
}

std::optional<Cone> tangent_cone(const SweptSphere& a, const SweptSphere& b) {
    const Vector3 along = b.center - a.center;
    const float d = length(along);
    if (!(d > std::abs(a.radius - b.radius))) return std::nullopt;  // one holds the other
    const Vector3 axis = along / d;
    const float sin_alpha = (a.radius - b.radius) / d;
    const float cos_alpha = std::sqrt(std::max(0.f, 1 - sin_alpha * sin_alpha));
    Cone cone;
    cone.base = a.center + axis * (a.radius * sin_alpha);
    cone.base_radius = a.radius * cos_alpha;
    cone.apex = a.center + axis * (d + b.radius * sin_alpha);
    cone.apex_radius = b.radius * cos_alpha;
    cone.capped = true;
    if (!describe_problem(cone).empty()) return std::nullopt;  // too thin to tell the ends apart
    return cone;
}

std::variant<SweepPieces, std::string> sweep_pieces(SweepSpline spline,
                                                    const std::vector<SweptSphere>& spheres,
                                                    float tolerance) {
    const std::size_t least = spline == SweepSpline::linear ? 2 : 4;
    const char* name = spline == SweepSpline::linear     ? "linear_spline"
                       : spline == SweepSpline::b_spline ? "b_spline"
                                                         : "cubic_spline";
    if (spheres.size() < least)
        return "sphere_sweep " + std::string(name) + " needs at least " + std::to_string(least) +
               " spheres, got " + std::to_string(spheres.size());
    // The chain of joints along the whole curve.
    std::vector<SweptSphere> chain;
    if (spline == SweepSpline::linear) {
        chain = spheres;
    } else {
        for (std::size_t segment = 0; segment + 3 < spheres.size(); ++segment) {
            const SweptSphere start = sweep_at(spline, spheres, segment, 0);
            if (chain.empty()) chain.push_back(start);
            cut(spline, spheres, segment, 0, 1, start, sweep_at(spline, spheres, segment, 1),
                tolerance, 0, chain);
        }
    }
    SweepPieces pieces;
    for (std::size_t i = 0; i < chain.size(); ++i) {
        if (!(chain[i].radius > 0))
            return "sphere_sweep's radius must be > 0 along its path, got " +
                   std::to_string(chain[i].radius);
        pieces.spheres.push_back({chain[i].center, chain[i].radius});
        if (i + 1 < chain.size())
            if (auto cone = tangent_cone(chain[i], chain[i + 1])) pieces.cones.push_back(*cone);
    }
    return pieces;
}

}  // namespace glint
