// The cylinder as a cone with equal radii, and the checks of its description.
#include "glint/geometry/cylinder.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "glint/geometry/cone.h"
#include "glint/geometry/disk.h"
#include "glint/math/constants.h"

namespace glint {

namespace {

// A cylinder is the frustum with equal radii: the cone's slope k is then exactly 0, its side
// equation |P - y a|^2 = r^2 and its normal the radial direction, so the cone's code serves both.
Cone as_cone(const Cylinder& c) { return {c.base, c.radius, c.top, c.radius, c.capped}; }

}  // namespace

Bounds3 Cylinder::bounds() const { return as_cone(*this).bounds(); }

std::optional<ShapeHit> Cylinder::intersect(const Ray& ray, Interval t_range) const {
    return as_cone(*this).intersect(ray, t_range);
}

SurfacePoint Cylinder::surface_at(const Ray& ray, const ShapeHit& hit) const {
    return as_cone(*this).surface_at(ray, hit);
}

std::string describe_problem(const Cylinder& cylinder) {
    std::ostringstream out;
    const float axis_length = length(cylinder.top - cylinder.base);
    if (!is_finite(cylinder.base) || !is_finite(cylinder.top)) {
        out << "cylinder base and top must be finite";
    } else if (!(cylinder.radius > 0) || !std::isfinite(cylinder.radius)) {
        out << "cylinder radius must be > 0, got " << cylinder.radius;
    } else if (!(axis_length > 0)) {
        out << "cylinder top must differ from its base";
    } else if (!std::isfinite(axis_length)) {
        out << "cylinder is too long: the distance from base to top overflows a float";
    }
    return out.str();
}

float Cylinder::area() const {
    const float side = 2 * kPi * radius * length(top - base);
    return capped ? side + 2 * kPi * radius * radius : side;
}

SurfaceSample Cylinder::sample(Point2 u) const {
    const Vector3 axis = top - base;
    const Vector3 a = normalize(axis);
    const float total = area(), side = 2 * kPi * radius * length(axis);
    float x = u.x * total;
    if (x >= side) {
        // A cap, picked by the rest of u.x.
        x -= side;
        const float cap = kPi * radius * radius;
        const bool at_top = x >= cap;
        const Disk disk =
            at_top ? Disk{top, Normal3(a), radius, 0} : Disk{base, Normal3(-a), radius, 0};
        const float along = std::min((at_top ? x - cap : x) / cap, 0x1.fffffep-1f);
        SurfaceSample s = disk.sample({along, u.y});
        s.pdf = 1 / total;
        return s;
    }
    Vector3 s, t;
    orthonormal_basis(a, s, t);
    const float phi = 2 * kPi * u.y;
    const Vector3 out = s * std::cos(phi) + t * std::sin(phi);
    return {base + axis * std::min(x / side, 1.0f) + out * radius, Normal3(out), 1 / total};
}

}  // namespace glint
