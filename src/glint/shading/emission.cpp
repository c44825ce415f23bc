// Where particles leave each kind of light, which way, and with what power.
#include "glint/shading/emission.h"

#include <cmath>
#include <variant>

#include "glint/math/constants.h"
#include "glint/sampling/warp.h"

namespace glint {

namespace {

// pi colour / quadratic: the intensity of a light falling off as 1 / (quadratic d^2).
Color intensity(Color color, const Attenuation& a) { return color * (kPi / a.quadratic); }

// A point of the disk of the scene's radius across `direction`, on the side it comes from.
Point3 entry_point(Vector3 direction, Point2 u, const SceneSphere& scene) {
    Vector3 s, t;
    orthonormal_basis(direction, s, t);
    const Point2 d = sample_uniform_disk(u);
    return scene.center + (s * d.x + t * d.y - direction) * scene.radius;
}

// A point drawn uniformly by area on an area light's shape.
Point3 point_on(const AreaLight& light, Point2 u) {
    return std::visit([u](const auto& shape) { return shape.sample(u).p; }, light.shape);
}

}  // namespace

EmittedParticle emit_particle(const Light& light, Point2 u_position, Point2 u_direction,
                              const SceneSphere& scene) {
    if (const auto* d = std::get_if<DirectionalLight>(&light))
        return {entry_point(d->direction, u_position, scene), d->direction,
                d->color * (kPi * kPi * scene.radius * scene.radius)};
    if (const auto* spot = std::get_if<SpotLight>(&light)) {
        // Uniform within the cone: nothing is sent beyond it.
        const Vector3 w =
            from_frame(sample_uniform_cone(u_direction, spot->cos_cone), spot->direction);
        const float pdf = uniform_cone_pdf(spot->cos_cone);
        return {spot->position, w,
                intensity(spot->color, spot->attenuation) *
                    (spot_factor(*spot, dot(w, spot->direction)) / pdf)};
    }
    const Vector3 w = sample_uniform_sphere(u_direction);
    if (const auto* point = std::get_if<PointLight>(&light))
        return {point->position, w,
                intensity(point->color, point->attenuation) * (1 / uniform_sphere_pdf())};
    const auto& area = std::get<AreaLight>(light);
    return {point_on(area, u_position), w,
            intensity(area.color, area.attenuation) * (1 / uniform_sphere_pdf())};
}

EmittedParticle emit_particle(const ObjectLight& light, Point2 u_position, Point2 u_direction) {
    const SurfaceSample s = light.surface.sample(u_position);
    Vector3 normal = to_vector(s.normal);
    float side_probability = 1;
    if (light.both_sides) {
        side_probability = 0.5f;
        if (u_direction.x < 0.5f) {
            normal = -normal;
            u_direction.x *= 2;
        } else {
            u_direction.x = (u_direction.x - 0.5f) * 2;
        }
    }
    // Cosine-weighted: Le cos / (pdf_A cos / pi) = pi Le / pdf_A.
    const Vector3 w = from_frame(sample_phong_lobe(u_direction, 1), normal);
    if (!(s.pdf > 0)) return {s.p, w, Color{}};
    return {s.p, w, light.radiance * (kPi / (s.pdf * side_probability))};
}

EmittedParticle emit_sky_particle(const Sky& sky, Point2 u_position, Point2 u_direction,
                                  const SceneSphere& scene) {
    float pdf = 0;
    const Vector3 to_sky = sky.sample(u_direction, &pdf);
    // Travelling along w: it comes from the sky towards -w.
    const Vector3 w = -to_sky;
    if (!(pdf > 0)) return {entry_point(w, u_position, scene), w, Color{}};
    return {entry_point(w, u_position, scene), w,
            sky.radiance(to_sky) * (kPi * scene.radius * scene.radius / pdf)};
}

Color sky_power(const Sky& sky, const SceneSphere& scene) {
    return sky.mean_radiance() * (4 * kPi * kPi * scene.radius * scene.radius);
}

LightSample sample_light_by_area(const Light& light, Point3 p, Point2 u) {
    if (const auto* area = std::get_if<AreaLight>(&light))
        return light_from_point(p, point_on(*area, u), area->color, area->attenuation);
    return sample_light(light, p);
}

}  // namespace glint
