// The slab test (Kay and Kajiya) for the box, remembering which face each slab crossing is on,
// and the face's normal and uv.
#include "glint/geometry/box.h"

#include <algorithm>
#include <cstdint>

namespace glint {

std::optional<ShapeHit> Box::intersect(const Ray& ray, Interval t_range) const {
    float t_near = -kInfinity, t_far = kInfinity;
    std::uint32_t near_face = 0, far_face = 0;
    for (int axis = 0; axis < 3; ++axis) {
        const float inv = 1 / ray.direction[axis];
        float t_min_side = (min[axis] - ray.origin[axis]) * inv;
        float t_max_side = (max[axis] - ray.origin[axis]) * inv;
        std::uint32_t enter = 2 * axis, leave = 2 * axis + 1;
        if (t_min_side > t_max_side) {
            std::swap(t_min_side, t_max_side);
            std::swap(enter, leave);
        }
        // A NaN (origin on a face plane, parallel direction) leaves the bounds as they were.
        if (t_min_side > t_near) t_near = t_min_side, near_face = enter;
        if (t_max_side < t_far) t_far = t_max_side, far_face = leave;
        if (t_near > t_far) return std::nullopt;
    }
    // An infinite t (a NaN or zero direction) is no hit.
    if (t_range.contains(t_near) && t_near < kInfinity) return ShapeHit{t_near, 0, 0, near_face};
    if (t_range.contains(t_far) && t_far < kInfinity) return ShapeHit{t_far, 0, 0, far_face};
    return std::nullopt;
}

SurfacePoint Box::surface_at(const Ray& ray, const ShapeHit& hit) const {
    const int axis = static_cast<int>(hit.part / 2);
    const bool max_side = hit.part % 2 == 1;
    const Point3 p = ray.at(hit.t);
    float c[3] = {p.x, p.y, p.z};
    c[axis] = max_side ? max[axis] : min[axis];  // snap onto the face
    SurfacePoint sp;
    sp.p = {c[0], c[1], c[2]};
    float n[3] = {0, 0, 0};
    n[axis] = max_side ? 1.0f : -1.0f;
    sp.normal = sp.shading_normal = {n[0], n[1], n[2]};
    const int a = (axis + 1) % 3, b = (axis + 2) % 3;
    const int u_axis = std::min(a, b), v_axis = std::max(a, b);
    sp.uv = {(c[u_axis] - min[u_axis]) / (max[u_axis] - min[u_axis]),
             (c[v_axis] - min[v_axis]) / (max[v_axis] - min[v_axis])};
    float du[3] = {0, 0, 0}, dv[3] = {0, 0, 0};
    du[u_axis] = max[u_axis] - min[u_axis];
    dv[v_axis] = max[v_axis] - min[v_axis];
    sp.dpdu = {du[0], du[1], du[2]};
    sp.dpdv = {dv[0], dv[1], dv[2]};
    sp.has_derivatives = true;
    return sp;
}

namespace {

// The area of each of the two faces across `axis`.
float face_area(const Box& b, int axis) {
    const Vector3 size = b.max - b.min;
    return size[(axis + 1) % 3] * size[(axis + 2) % 3];
}

}  // namespace

float Box::area() const {
    return 2 * (face_area(*this, 0) + face_area(*this, 1) + face_area(*this, 2));
}

SurfaceSample Box::sample(Point2 u) const {
    // A face picked by its area with u.x, which is then stretched back over [0, 1).
    const float total = area();
    float x = u.x * total;
    int face = 0;
    for (; face < 5; ++face) {
        const float a = face_area(*this, face / 2);
        if (x < a) break;
        x -= a;
    }
    const int axis = face / 2;
    const int i = (axis + 1) % 3, j = (axis + 2) % 3;
    const float a = face_area(*this, axis);
    const float along_i = std::min(x / a, 0x1.fffffep-1f);
    const bool max_side = face % 2 == 1;
    float p[3], n[3] = {0, 0, 0};
    p[axis] = max_side ? max[axis] : min[axis];
    p[i] = min[i] + (max[i] - min[i]) * along_i;
    p[j] = min[j] + (max[j] - min[j]) * u.y;
    n[axis] = max_side ? 1.0f : -1.0f;
    return {{p[0], p[1], p[2]}, Normal3(n[0], n[1], n[2]), 1 / total};
}

}  // namespace glint
