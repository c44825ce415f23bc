// The watertight ray/triangle test (Woop, Benthin and Wald 2013). Built, as all of glint, with
// -ffp-contract=off (see CMakeLists.txt): a fused multiply-add would round some products and not
// others, and the edge functions' signs would no longer be exact.
#include "glint/geometry/watertight_triangle.h"

#include <cmath>
#include <limits>

namespace glint {

namespace {

// Components by a run-time axis, read from memory: Vector3::operator[] compiles to branches,
// which the random axes of incoherent rays mispredict.
struct Components {
    float c[3];
    explicit Components(Vector3 v) : c{v.x, v.y, v.z} {}
    float operator[](int axis) const { return c[axis]; }
};

// A vertex in the ray's sheared frame, where the ray runs from (0, 0, 0) along +z. z is left
// unscaled: only hits that pass the edge tests pay for the multiplication by sz.
struct Sheared {
    float x, y, z;
};

Sheared shear_vertex(Point3 v, const Ray& ray, const RayShear& s) {
    const Components p(v - ray.origin);
    const float z = p[s.kz];
    return {p[s.kx] - s.sx * z, p[s.ky] - s.sy * z, z};
}

// The edge function of p -> q in the sheared plane (the paper's U, V, W): a triangle's three
// share a sign when the ray passes inside it, positive when it meets the front side. The float
// result is 0 or of the exact sign, as rounding a product is monotonic in its exact value; when
// it is 0 the exact products in double decide, as the paper does.
float edge_function(Sheared p, Sheared q) {
    const float e = q.x * p.y - q.y * p.x;
    if (e != 0) return e;
    return float(double(q.x) * double(p.y) - double(q.y) * double(p.x));
}

// The test proper, inlined into both entry points: when the shear is made per call, it then
// stays in registers instead of making a round trip through memory.
inline std::optional<ShapeHit> intersect_sheared(Point3 v0, Point3 v1, Point3 v2, const Ray& ray,
                                                 const RayShear& shear, Interval t_range) {
    const Sheared a = shear_vertex(v0, ray, shear);
    const Sheared b = shear_vertex(v1, ray, shear);
    const Sheared c = shear_vertex(v2, ray, shear);
    // w_i is det times the barycentric weight of v_i, the vertex opposite its edge.
    const float w0 = edge_function(b, c);
    const float w1 = edge_function(c, a);
    const float w2 = edge_function(a, b);
    // Two-sided: inside when no two signs differ; a zero (on an edge) goes with either side.
    // Bitwise, not short-circuit: the signs of random rays are unpredictable branches.
    const bool any_negative = (w0 < 0) | (w1 < 0) | (w2 < 0);
    const bool any_positive = (w0 > 0) | (w1 > 0) | (w2 > 0);
    if (any_negative & any_positive) return std::nullopt;
    const float det = w0 + w1 + w2;
    // Zero: the ray lies in the triangle's plane, or the triangle has no area seen along it.
    // NaN (from any NaN input) passes the sign test above and stops here.
    if (det == 0 || !std::isfinite(det)) return std::nullopt;
    // The shear rounds, so exactly collinear corners can still give det != 0 for a ray that
    // passes right by their line. Only candidates pay for this check.
    const Vector3 normal = cross(v1 - v0, v2 - v0);
    if (normal.x == 0 && normal.y == 0 && normal.z == 0) return std::nullopt;

    // t * det. Hits beyond the range's far end (behind a nearer hit already found) are dropped
    // before the division, comparing with the far end scaled by |det|. The comparison allows
    // 16 ulps (and FLT_MIN where the product underflows), more than the division below can
    // move t, so it never drops a t that the exact test below keeps: a triangle's hit does not
    // depend on how far the range reaches past it, and aggregates that narrow the range in
    // different orders agree at equal t.
    const float t_scaled = shear.sz * (w0 * a.z + w1 * b.z + w2 * c.z);
    const float signed_t = det < 0 ? -t_scaled : t_scaled;
    const float far = t_range.max * std::abs(det);
    constexpr float kTiny = std::numeric_limits<float>::min();
    if (t_range.max >= kTiny && signed_t > far + far * 0x1p-20f + kTiny) return std::nullopt;
    const float inv_det = 1 / det;
    const float t = t_scaled * inv_det;
    // Whether it is in range is decided on t itself; an overflow makes it infinite.
    if (!std::isfinite(t) || !t_range.contains(t)) return std::nullopt;
    return ShapeHit{t, w1 * inv_det, w2 * inv_det};
}

}  // namespace

std::optional<ShapeHit> intersect_watertight(Point3 v0, Point3 v1, Point3 v2, const Ray& ray,
                                             const RayShear& shear, Interval t_range) {
    return intersect_sheared(v0, v1, v2, ray, shear, t_range);
}

std::optional<ShapeHit> intersect_watertight(Point3 v0, Point3 v1, Point3 v2, const Ray& ray,
                                             Interval t_range) {
    return intersect_sheared(v0, v1, v2, ray, RayShear(ray.direction), t_range);
}

}  // namespace glint
