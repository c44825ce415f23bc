// What a point receives from each kind of light: direction, distance and attenuated intensity,
// from the light's centre or from a point drawn on it.
#include "glint/shading/light.h"

#include <algorithm>
#include <cmath>

#include "glint/math/constants.h"
#include "glint/math/interval.h"
#include "glint/sampling/warp.h"

namespace glint {

namespace {

// pbrt-v4's smoothstep of cos(angle) between the cone's edge and the falloff's start.
float spot_factor(const SpotLight& light, Vector3 to_light) {
    const float c = -dot(to_light, light.direction);
    if (c >= light.cos_falloff) return 1;
    if (c <= light.cos_cone) return 0;
    const float t = (c - light.cos_cone) / (light.cos_falloff - light.cos_cone);
    return t * t * (3 - 2 * t);
}

Point3 center_of(const AreaLight& light) {
    return std::visit([](const auto& shape) { return shape.center; }, light.shape);
}

// A point of the light's shape, as seen from p.
struct DrawPoint {
    Point3 p;
    Point2 u;

    Point3 operator()(const SphereLight& s) const {
        const Vector3 to_center = s.center - p;
        const float d2 = length_squared(to_center);
        const float r2 = s.radius * s.radius;
        if (d2 <= r2) return s.center + sample_uniform_sphere(u) * s.radius;  // p inside
        // Uniform over the cone of directions the sphere fills, then the near side along it.
        const float d = std::sqrt(d2);
        const float cos_max = std::sqrt(std::max(0.0f, 1 - r2 / d2));
        const Vector3 w = from_frame(sample_uniform_cone(u, cos_max), to_center / d);
        const float b = dot(w, to_center);
        const float t = b - std::sqrt(std::max(0.0f, r2 - (d2 - b * b)));
        return p + w * t;
    }
    Point3 operator()(const DiskLight& disk) const {
        Vector3 s, t;
        orthonormal_basis(to_vector(disk.normal), s, t);
        const Point2 q = sample_uniform_disk(u);
        return disk.center + (s * q.x + t * q.y) * disk.radius;
    }
    Point3 operator()(const RectangleLight& r) const {
        return r.center + r.u * (u.x - 0.5f) + r.v * (u.y - 0.5f);
    }
};

struct AtCenter {
    Point3 p;

    LightSample operator()(const PointLight& light) const {
        return light_from_point(p, light.position, light.color, light.attenuation);
    }
    LightSample operator()(const SpotLight& light) const {
        LightSample s = light_from_point(p, light.position, light.color, light.attenuation);
        s.intensity *= spot_factor(light, s.to_light);
        return s;
    }
    LightSample operator()(const DirectionalLight& light) const {
        return {-light.direction, kInfinity, light.color};
    }
    LightSample operator()(const AreaLight& light) const {
        return light_from_point(p, center_of(light), light.color, light.attenuation);
    }
};

}  // namespace

LightSample sample_light_at_center(const Light& light, Point3 p) {
    return std::visit(AtCenter{p}, light);
}

LightSample sample_light(const Light& light, Point3 p, Point2 u) {
    if (const auto* area = std::get_if<AreaLight>(&light))
        return light_from_point(p, std::visit(DrawPoint{p, u}, area->shape), area->color,
                                area->attenuation);
    return sample_light(light, p);
}

bool is_area_light(const Light& light) { return std::holds_alternative<AreaLight>(light); }

namespace {

Color power_of(Color color, const Attenuation& a, float r) {
    return color * (4 * kPi * kPi * r * r / (a.constant + r * (a.linear + r * a.quadratic)));
}

struct PowerOf {
    float r;
    Color operator()(const PointLight& l) const { return power_of(l.color, l.attenuation, r); }
    Color operator()(const SpotLight& l) const {
        // The solid angle of the cone, the falloff counted half (pbrt-v4's estimate).
        const float share = (1 - 0.5f * (l.cos_cone + l.cos_falloff)) / 2;
        return power_of(l.color, l.attenuation, r) * share;
    }
    Color operator()(const DirectionalLight& l) const { return l.color * (kPi * kPi * r * r); }
    Color operator()(const AreaLight& l) const { return power_of(l.color, l.attenuation, r); }
};

bool falls_off_as_inverse_square(const Attenuation& a) {
    return a.constant == 0 && a.linear == 0 && a.quadratic > 0;
}

}  // namespace

Color light_power(const Light& light, float scene_radius) {
    return std::visit(PowerOf{scene_radius}, light);
}

bool emits_finite_power(const Light& light) {
    if (std::holds_alternative<DirectionalLight>(light)) return true;
    return std::visit(
        [](const auto& l) {
            if constexpr (requires { l.attenuation; })
                return falls_off_as_inverse_square(l.attenuation);
            else
                return true;
        },
        light);
}

}  // namespace glint
