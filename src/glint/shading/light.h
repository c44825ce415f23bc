// Light sources: point and spot lights (with optional distance attenuation), directional lights,
// and area lights (sphere, disk, rectangle) that cast soft shadows. The global ambient term lives
// in the scene; objects that emit light are lights of their own (object_light.h).
#pragma once

#include <optional>
#include <variant>

#include "glint/geometry/disk.h"
#include "glint/geometry/polygon.h"
#include "glint/geometry/sphere.h"
#include "glint/math/color.h"
#include "glint/math/vector.h"

namespace glint {

// Intensity at distance d is color / (constant + linear d + quadratic d^2).
struct Attenuation {
    float constant = 1;
    float linear = 0;
    float quadratic = 0;
};

// Every light casts shadows unless `casts_shadows` is false: then its shadow feelers are not
// traced and it lights every surface facing it, as POV-Ray's shadowless fill lights do.
struct PointLight {
    Point3 position;
    Color color{1, 1, 1};
    Attenuation attenuation;
    bool casts_shadows = true;
    bool in_media = true;  // scatters in participating media
};

// A point light that shines into a cone: full intensity within the falloff's start, none beyond
// the cone, and a smoothstep in cos(angle) between (as pbrt-v4's spot light); tightened towards
// its axis as POV-Ray's.
struct SpotLight {
    Point3 position;
    Vector3 direction{0, -1, 0};  // unit; the cone's axis, the way the light shines
    float cos_cone = 0.866025f;   // cosine of the cone's half-angle: dark beyond
    float cos_falloff =
        0.866025f;  // cosine of the half-angle where the falloff starts; >= cos_cone
    // POV-Ray's tightness: the intensity falls as cos(angle)^tightness from the axis, across
    // the cone; 0 leaves it even. >= 0.
    float tightness = 0;
    Color color{1, 1, 1};
    Attenuation attenuation;
    bool casts_shadows = true;
    bool in_media = true;  // scatters in participating media
};

// The share of a spot light's intensity that leaves it at cos_angle from its axis: the rim's
// smoothstep times cos^tightness.
float spot_factor(const SpotLight& light, float cos_angle);

struct DirectionalLight {
    Vector3 direction{0, -1, 0};  // unit; the way the light travels
    Color color{1, 1, 1};
    bool casts_shadows = true;
    bool in_media = true;  // scatters in participating media
};

// A light with an extent, for soft shadows (Cook, Porter and Carpenter 1984). Its colour is that
// of a point light spread over the shape, as POV-Ray's area lights do: a point drawn on it lights
// a surface like a point light of the whole colour there, so that averaging over the points gives
// the penumbra, and a small area light looks like a point light. A sphere is sampled by the cone
// of directions it fills as seen from the surface, a disk and a rectangle uniformly by area: each
// shape draws its own points (Sphere::sample_seen_from, Disk::sample, Polygon::sample). Each
// emits to both sides. Made by sphere_light, disk_light and rectangle_light below.
struct AreaLight {
    std::variant<Sphere, Disk, Polygon> shape;  // the polygon a rectangle
    Point3 center;                              // where Whitted's ray tracer puts it
    Color color{1, 1, 1};
    Attenuation attenuation;
    // Shadow rays a sample sends to it; 0 takes the scene's image.shadow_rays.
    int shadow_rays = 0;
    bool casts_shadows = true;
    bool in_media = true;  // scatters in participating media
};

AreaLight sphere_light(Point3 center, float radius);
AreaLight disk_light(Point3 center, Normal3 normal, float radius);  // normal unit
// The rectangle center + a u + b v for a and b in [-1/2, 1/2]; nothing when u and v make none
// (zero, parallel or too large to measure).
std::optional<AreaLight> rectangle_light(Point3 center, Vector3 u, Vector3 v);

// The point of the light's shape that a shadow ray from p aims at, drawn from u in [0,1)^2.
Point3 point_seen_from(const AreaLight& light, Point3 p, Point2 u);

using Light = std::variant<PointLight, SpotLight, DirectionalLight, AreaLight>;

inline bool casts_shadows(const Light& light) {
    return std::visit([](const auto& l) { return l.casts_shadows; }, light);
}

// Whether the light scatters in participating media (POV-Ray's media_interaction).
inline bool scatters_in_media(const Light& light) {
    return std::visit([](const auto& l) { return l.in_media; }, light);
}

// What a surface point receives from one light, before shadowing.
struct LightSample {
    Vector3 to_light;  // unit direction L from the point towards the light (or a point of it)
    float distance;    // to that point; infinite for directional lights
    Color intensity;   // I_L, attenuated; black when the light does not shine this way
};

// What p receives from the point q of a light of the given colour: nothing when p is q.
inline LightSample light_from_point(Point3 p, Point3 q, Color color, const Attenuation& a) {
    const Vector3 offset = q - p;
    const float d = length(offset);
    if (!(d > 0)) return {{0, 1, 0}, 0, Color{}};  // on the light itself: nothing to trace
    return {offset / d, d, color / (a.constant + d * (a.linear + d * a.quadratic))};
}

// sample_light below for every kind of light.
LightSample sample_light_at_center(const Light& light, Point3 p);

// What p receives from the light as Whitted's ray tracer sees it: an area light acts as a point
// light at its centre. Point lights, the most common, skip the dispatch over the kinds: this is
// asked at every hit for every light.
inline LightSample sample_light(const Light& light, Point3 p) {
    if (const auto* point = std::get_if<PointLight>(&light))
        return light_from_point(p, point->position, point->color, point->attenuation);
    return sample_light_at_center(light, p);
}

// What p receives from a point of the light drawn from u in [0,1)^2; lights without an extent
// ignore u.
LightSample sample_light(const Light& light, Point3 p, Point2 u);

// Whether the light has an extent, so that shadow rays towards it differ from sample to sample.
bool is_area_light(const Light& light);

// The power the light sends into the scene, for picking lights in proportion to it. A light
// whose intensity I_L lights a surface facing it with irradiance pi I_L (so that Phong's
// diffuse term is Lambert's), which falls off as 1 / (c + l d + q d^2): the power through a
// sphere of radius `scene_radius` around it, 4 pi^2 R^2 I_L / (c + l R + q R^2), the whole
// power for a light that falls off as 1 / d^2; a spot light's share of it within its cone; a
// directional light's through the scene's disk, pi I_L pi R^2.
Color light_power(const Light& light, float scene_radius);

// Whether the light has a power of its own, which particles leaving it can carry: a directional
// light, or one whose intensity falls off as 1 / d^2 alone (attenuation constant and linear 0).
bool emits_finite_power(const Light& light);

}  // namespace glint
