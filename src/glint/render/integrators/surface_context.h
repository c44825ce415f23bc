// What every integrator needs to know where a ray meets a surface: the point, its material and
// colour there, which side the ray came from, and both normals turned towards the ray. Built
// once per hit, the same way for every integrator.
#pragma once

#include "glint/accel/aggregate.h"
#include "glint/geometry/surface_point.h"
#include "glint/math/color.h"
#include "glint/math/ray.h"
#include "glint/render/integrators/medium_stack.h"
#include "glint/render/pencil.h"
#include "glint/render/world.h"
#include "glint/shading/bsdf.h"
#include "glint/shading/material.h"
#include "glint/shading/optics.h"
#include "glint/shading/texture.h"

namespace glint {

struct SurfaceContext {
    SurfacePoint sp;
    std::uint32_t primitive;  // the object hit
    const Material* material;
    Color color;          // the material's colour (texture) at the point, C of the formulas
    Color ambient_color;  // C of the ambient term: the same, but for layers (LayeredTexture)
    Color emission;       // what it emits towards the ray: none from the back of a one-sided one
    bool entering;        // the ray meets the front (outward) side
    Normal3 ng;           // geometric normal on the ray's side: where secondary rays start
    Normal3 n;            // shading normal on the ray's side: what the formulas use
    Vector3 to_viewer;    // -direction of the ray, V
    // The material's reflect, roughness and transmit_roughness at the point (maps evaluated;
    // reflect at the ray's angle when it varies with it).
    float reflect, roughness, transmit_roughness;
    // What the mirror-reflected light is multiplied by besides reflect: the material's
    // reflect_color, and a metallic reflection's colour.
    Color reflect_color{1, 1, 1};
    // The ray's pencil where it meets the surface, when the ray carries one (pencil.h).
    std::optional<PencilAtSurface> pencil;
};

// The ray enters the surface when it meets the front side. Both normals are turned to face the
// incoming ray: the geometric one places secondary rays on the right side of the surface, the
// shading one (smooth for meshes) enters the formulas. A ray that carries its pencil gives the
// texture lookup its footprint.
inline SurfaceContext surface_context(const World& world, const Ray& ray, const Hit& hit,
                                      const RayDifferential* pencil = nullptr) {
    SurfaceContext c;
    c.primitive = hit.primitive;
    c.material = &world.material_at(hit);
    const Material& m = *c.material;
    c.sp = world.surface_at(ray, hit, pencil ? Uv::compute : uv_needed(m.color));
    if (pencil) {
        c.pencil = pencil_at(ray, *pencil, hit.shape_hit.t, c.sp);
        c.sp.footprint = c.pencil->footprint;
    }
    if (const auto* layered = std::get_if<LayeredTexturePtr>(&m.color)) [[unlikely]] {
        const LayeredColors colors = evaluate_layers(**layered, c.sp);
        c.color = colors.diffuse;
        c.ambient_color = colors.ambient;
    } else {
        c.color = evaluate(m.color, c.sp);
        c.ambient_color = c.color;
    }
    c.reflect = m.reflect;
    c.reflect_color = m.reflect_color;
    c.roughness = m.roughness;
    c.transmit_roughness = m.transmit_roughness;
    if (m.maps) [[unlikely]] {
        const MaterialMaps& maps = *m.maps;
        if (maps.reflect) c.reflect = evaluate(*maps.reflect, c.sp.p);
        if (maps.roughness) c.roughness = evaluate(*maps.roughness, c.sp.p);
        if (maps.transmit_roughness)
            c.transmit_roughness = evaluate(*maps.transmit_roughness, c.sp.p);
        if (maps.bump) c.sp.shading_normal = bumped(*maps.bump, c.sp.shading_normal, c.sp.p);
        if (maps.normal_pattern)
            c.sp.shading_normal = perturbed(*maps.normal_pattern, c.sp.shading_normal, c.sp.p);
    }
    c.entering = dot(c.sp.normal, ray.direction) < 0;
    if (m.emits_both_sides || c.entering) {
        c.emission = m.emission;
        if (m.maps) c.emission += c.ambient_color * m.maps->color_emission;
    }
    c.ng = c.entering ? c.sp.normal : -c.sp.normal;
    c.n = c.entering ? c.sp.shading_normal : -c.sp.shading_normal;
    c.to_viewer = -ray.direction;
    if (m.reflect_angular || m.reflect_metallic > 0) [[unlikely]] {
        // By the angle to the shading normal; Fresnel's by the object's own index against
        // vacuum's, whichever objects it lies in.
        const float cos_theta = dot(c.n, c.to_viewer);
        if (m.reflect_angular)
            c.reflect = reflect_at(*m.reflect_angular, c.reflect, cos_theta,
                                   c.entering ? 1 / m.ior : m.ior);
        if (m.reflect_metallic > 0)
            c.reflect_color *= metallic_reflection(m.reflect_metallic, c.color, cos_theta);
    }
    return c;
}

// A secondary ray from the surface point in the unit direction d, at its parent's time and
// wavelength.
inline Ray spawn_from(const World& world, const SurfaceContext& c, const Ray& parent, Vector3 d) {
    Ray r = world.spawn_ray(c.sp.p, c.ng, d, c.sp.error, parent.time);
    r.wavelength = parent.wavelength;
    return r;
}

// The pencils of the rays that leave c as a mirror reflects and as glass refracts (eta = n1 / n2)
// a ray that carried `pencil`: none when it carried none, or when the shape does not say how its
// normal bends.
inline std::optional<RayDifferential> mirror_pencil(const SurfaceContext& c, const Ray& ray,
                                                    const RayDifferential* pencil) {
    if (!pencil || !c.pencil || !c.pencil->bends_known) return std::nullopt;
    return reflected_pencil(ray, *pencil, *c.pencil, c.n, c.entering ? 1.0f : -1.0f);
}
inline std::optional<RayDifferential> refraction_pencil(const SurfaceContext& c, const Ray& ray,
                                                        const RayDifferential* pencil, float eta,
                                                        Vector3 refracted) {
    if (!pencil || !c.pencil || !c.pencil->bends_known) return std::nullopt;
    return refracted_pencil(ray, *pencil, *c.pencil, c.n, c.entering ? 1.0f : -1.0f, eta,
                            refracted);
}
inline const RayDifferential* or_null(const std::optional<RayDifferential>& pencil) {
    return pencil ? &*pencil : nullptr;
}

// The weights of the reflected and refracted rays at the surface and the refracted direction:
// kr and kt of the material, Snell's law with the indices of the media on both sides, and on
// total internal reflection the transmitted weight moved to the reflected ray (Whitted 1980);
// with fresnel, the share kt F of Fresnel's reflectance moved likewise.
// The material's index of refraction for a ray of the given wavelength (0: one that carries
// every wavelength, which sees the index at the d line).
inline float ior_at(const Material& m, float wavelength) {
    if (m.dispersion.model == DispersionModel::none || wavelength == 0) return m.ior;
    return refractive_index(m.dispersion, m.ior, wavelength);
}

struct Branches {
    float kr = 0, kt = 0;
    Color filter{1, 1, 1};  // the refracted ray's colour besides kt (transmit_filter)
    // The reflected ray's colour besides kr: the surface's own reflection's colour
    // (reflect_color), not that of the light moved to it by Fresnel or total reflection.
    Color reflect_filter{1, 1, 1};
    Vector3 refracted;  // unit; when kt > 0
    bool entering;      // the refracted ray enters the object (else it leaves it)
    float eta = 1;      // n1 / n2 of the refraction, when kt > 0
};

// What light crossing a surface of colour `surface` is multiplied by besides kt: the
// colour's share (Material::tint), as coloured glass filters it.
inline Color tint_filter(float tint, const Color& surface) {
    return Color::gray(1 - tint) + tint * surface;
}

// The tint filter of the light refracted at c.
inline Color transmit_filter(const SurfaceContext& c) {
    const float tint = c.material->tint;
    if (tint == 0) [[likely]]
        return Color{1, 1, 1};
    return tint_filter(tint, c.color);
}

// Snell's law's indices at c: n1 on the ray's side, n2 beyond.
struct SnellIndices {
    float n1, n2;
};
inline SnellIndices snell_indices(const SurfaceContext& c, const MediumStack& media,
                                  float wavelength) {
    const float ior = ior_at(*c.material, wavelength);
    return c.entering ? SnellIndices{media.ior(), ior}
                      : SnellIndices{ior, media.ior_after_leaving(c.primitive, c.material)};
}

inline Branches branches_at(const SurfaceContext& c, Vector3 direction, const MediumStack& media,
                            float wavelength = 0) {
    const Material& m = *c.material;
    Branches b{c.reflect, m.transmit, {1, 1, 1}, {1, 1, 1}, {}, c.entering};
    if (b.kt > 0) {
        const auto [n1, n2] = snell_indices(c, media, wavelength);
        if (const auto t = refract(direction, c.n, n1 / n2)) {
            b.refracted = normalize(*t);
            b.eta = n1 / n2;
            b.filter = transmit_filter(c);
            if (m.fresnel) {  // kt F of it reflects
                const float reflected =
                    b.kt * fresnel_dielectric(-dot(direction, to_vector(c.n)), n1 / n2);
                b.kr += reflected;
                b.kt -= reflected;
            }
        } else {  // total internal reflection
            b.kr += b.kt;
            b.kt = 0;
        }
    }
    if (c.reflect_color != Color{1, 1, 1} && b.kr > 0) [[unlikely]]
        b.reflect_filter = (c.reflect * c.reflect_color + Color::gray(b.kr - c.reflect)) / b.kr;
    return b;
}

// The media the refracted ray of b travels through, for a ray in `media` at c.
inline MediumStack media_beyond(const SurfaceContext& c, const Branches& b,
                                const MediumStack& media, float wavelength = 0) {
    const Material& m = *c.material;
    return b.entering ? media.entered(c.primitive, &m, ior_at(m, wavelength))
                      : media.left(c.primitive, &m);
}

// The material at c read as a BSDF's numbers (bsdf.h), for indices eta on both sides.
inline BsdfInputs bsdf_inputs(const SurfaceContext& c, SnellIndices eta) {
    const Material& m = *c.material;
    BsdfInputs in;
    in.wo = c.to_viewer;
    in.n = c.n;
    in.ng = c.ng;
    in.kd = m.kd;
    in.color = c.color;
    in.ks = m.ks;
    in.shininess = m.shininess;
    in.reflect = c.reflect;
    in.reflect_filter = c.reflect_color;
    in.roughness = c.roughness;
    in.transmit = m.transmit;
    in.transmit_filter = transmit_filter(c);
    in.transmit_roughness = c.transmit_roughness;
    in.n1 = eta.n1;
    in.n2 = eta.n2;
    in.fresnel = m.fresnel;
    return in;
}

}  // namespace glint
