// What a point receives from each kind of light: direction, distance and attenuated intensity,
// from the light's centre or from a point drawn on it.
#include "glint/shading/light.h"

#include <algorithm>
#include <cmath>

#include "glint/math/constants.h"
#include "glint/math/interval.h"
#include "glint/sampling/warp.h"

namespace glint {

float spot_factor(const SpotLight& light, float c) {
    if (c <= light.cos_cone) return 0;
    // pbrt-v4's smoothstep of cos(angle) between the cone's edge and the falloff's start.
    float rim = 1;
    if (c < light.cos_falloff) {
        const float t = (c - light.cos_cone) / (light.cos_falloff - light.cos_cone);
        rim = t * t * (3 - 2 * t);
    }
    return light.tightness > 0 && c > 0 ? rim * std::pow(c, light.tightness) : rim;
}

namespace {

struct AtCenter {
    Point3 p;

    LightSample operator()(const PointLight& light) const {
        return light_from_point(p, light.position, light.color, light.attenuation);
    }
    LightSample operator()(const SpotLight& light) const {
        LightSample s = light_from_point(p, light.position, light.color, light.attenuation);
        s.intensity *= spot_factor(light, -dot(s.to_light, light.direction));
        return s;
    }
    LightSample operator()(const DirectionalLight& light) const {
        return {-light.direction, kInfinity, light.color};
    }
    LightSample operator()(const AreaLight& light) const {
        return light_from_point(p, light.center, light.color, light.attenuation);
    }
};

}  // namespace

AreaLight sphere_light(Point3 center, float radius) {
    AreaLight light;
    light.shape = Sphere{center, radius};
    light.center = center;
    return light;
}

AreaLight disk_light(Point3 center, Normal3 normal, float radius) {
    AreaLight light;
    light.shape = Disk{center, normal, radius, 0};
    light.center = center;
    return light;
}

std::optional<AreaLight> rectangle_light(Point3 center, Vector3 u, Vector3 v) {
    const Vector3 hu = u * 0.5f, hv = v * 0.5f;
    auto polygon =
        make_polygon({center - hu - hv, center + hu - hv, center + hu + hv, center - hu + hv});
    if (!std::holds_alternative<Polygon>(polygon)) return std::nullopt;
    AreaLight light;
    light.shape = std::get<Polygon>(std::move(polygon));
    light.center = center;
    return light;
}

Point3 point_seen_from(const AreaLight& light, Point3 p, Point2 u) {
    if (const auto* sphere = std::get_if<Sphere>(&light.shape))
        return sphere->sample_seen_from(p, u).p;
    return std::visit([u](const auto& shape) { return shape.sample(u).p; }, light.shape);
}

LightSample sample_light_at_center(const Light& light, Point3 p) {
    return std::visit(AtCenter{p}, light);
}

LightSample sample_light(const Light& light, Point3 p, Point2 u) {
    if (const auto* area = std::get_if<AreaLight>(&light))
        return light_from_point(p, point_seen_from(*area, p, u), area->color, area->attenuation);
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
