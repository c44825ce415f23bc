// The cylinder as a cone with equal radii, and the checks of its description.
#include "glint/geometry/cylinder.h"

#include <cmath>
#include <sstream>

#include "glint/geometry/cone.h"

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

}  // namespace glint
