// Igehy's ray differentials: transfer, the texture footprint, reflection and refraction.
#include "glint/render/pencil.h"

#include <algorithm>
#include <cmath>

namespace glint {

RayDifferential eye_pencil(const Camera& camera, const Ray& ray, Point2 film, Point2 lens,
                           float time, float scale) {
    const Ray x = camera.generate_ray({film.x + 1, film.y}, lens, time);
    const Ray y = camera.generate_ray({film.x, film.y + 1}, lens, time);
    return {(x.origin - ray.origin) * scale, (y.origin - ray.origin) * scale,
            (x.direction - ray.direction) * scale, (y.direction - ray.direction) * scale};
}

float eye_pencil_scale(int samples) {
    return std::max(0.125f, 1 / std::sqrt(float(std::max(samples, 1))));
}

namespace {

// The step dp in the tangent plane as du dp/du + dv dp/dv, by least squares (dp lies in the
// plane the two span, so the fit is exact where they are independent).
Point2 uv_step(const SurfacePoint& sp, Vector3 dp) {
    const float a = dot(sp.dpdu, sp.dpdu), b = dot(sp.dpdu, sp.dpdv), c = dot(sp.dpdv, sp.dpdv);
    const float det = a * c - b * b;
    if (!(std::abs(det) > 1e-20f)) return {0, 0};
    const float pu = dot(sp.dpdu, dp), pv = dot(sp.dpdv, dp);
    const Point2 step{(c * pu - b * pv) / det, (a * pv - b * pu) / det};
    return std::isfinite(step.x) && std::isfinite(step.y) ? step : Point2{0, 0};
}

}  // namespace

PencilAtSurface pencil_at(const Ray& ray, const RayDifferential& pencil, float t,
                          const SurfacePoint& sp) {
    const Vector3 d = ray.direction;
    const Vector3 n = to_vector(sp.normal);
    // A grazing ray's pencil spreads without bound; this keeps it finite.
    const float dn = std::copysign(std::max(std::abs(dot(d, n)), 1e-4f), dot(d, n));
    auto transfer = [&](Vector3 dodx, Vector3 dddx) {
        const Vector3 dp = dodx + dddx * t;
        return dp - d * (dot(dp, n) / dn);  // dt = -(dp.N) / (D.N)
    };
    PencilAtSurface at;
    at.dpdx = transfer(pencil.dodx, pencil.dddx);
    at.dpdy = transfer(pencil.dody, pencil.dddy);
    at.bends_known = sp.has_derivatives;
    if (!sp.has_derivatives) return at;
    const Point2 x = uv_step(sp, at.dpdx), y = uv_step(sp, at.dpdy);
    at.footprint = {x.x, x.y, y.x, y.y};
    at.dndx = sp.dndu * x.x + sp.dndv * x.y;
    at.dndy = sp.dndu * y.x + sp.dndv * y.y;
    return at;
}

RayDifferential reflected_pencil(const Ray& ray, const RayDifferential& pencil,
                                 const PencilAtSurface& at, Normal3 n, float side) {
    const Vector3 d = ray.direction, nv = to_vector(n);
    const float dn = dot(d, nv);
    // R = D - 2 (D.N) N, so dR = dD - 2 ((D.N) dN + d(D.N) N) with d(D.N) = dD.N + D.dN.
    auto turn = [&](Vector3 ddd, Vector3 dnd) {
        const Vector3 dn_step = dnd * side;
        return ddd - (dn_step * dn + nv * (dot(ddd, nv) + dot(d, dn_step))) * 2;
    };
    return {at.dpdx, at.dpdy, turn(pencil.dddx, at.dndx), turn(pencil.dddy, at.dndy)};
}

RayDifferential refracted_pencil(const Ray& ray, const RayDifferential& pencil,
                                 const PencilAtSurface& at, Normal3 n, float side, float eta,
                                 Vector3 refracted) {
    const Vector3 d = ray.direction, nv = to_vector(n);
    const float dn = dot(d, nv), tn = dot(refracted, nv);
    // T = eta D - mu N with mu = eta (D.N) - T.N, so dT = eta dD - (mu dN + dmu N), where
    // dmu = (eta - eta^2 (D.N) / (T.N)) d(D.N).
    const float mu = eta * dn - tn;
    const float dmu_ddn = tn != 0 ? eta - eta * eta * dn / tn : 0;
    auto bend = [&](Vector3 ddd, Vector3 dnd) {
        const Vector3 dn_step = dnd * side;
        const float dmu = dmu_ddn * (dot(ddd, nv) + dot(d, dn_step));
        return ddd * eta - (dn_step * mu + nv * dmu);
    };
    return {at.dpdx, at.dpdy, bend(pencil.dddx, at.dndx), bend(pencil.dddy, at.dndy)};
}

float pencil_width(const PencilAtSurface& at) { return std::max(length(at.dpdx), length(at.dpdy)); }

}  // namespace glint
