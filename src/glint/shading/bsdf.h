// A material read as a scattering function (BSDF) for the physically based integrators (path,
// light, photon): f(wo, wi) per steradian, the density its samples are drawn with, and the
// samples themselves. Its parts, each weighted by the material's coefficient:
//   diffuse    kd C / pi                                  (Lambert)
//   highlight  ks (n+2)/(2 pi) cos^n(alpha), alpha between wi and wo mirrored about N
//              (the normalised Phong lobe of Lafortune and Willems 1994; it reflects <= ks)
//   reflect    kr F_r: a mirror, or with roughness r the glossy lobe of the distributed
//              integrator, (m+1)/(2 pi) cos^m(alpha) / |N.wi| with m = 2/r^2 - 2, whose
//              samples each weigh kr as Cook's glossy rays do
//   transmit   kt F_t: Snell's refracted direction, or the lobe of transmit_roughness around it,
//              coloured by the filter F_t;
//              with fresnel, kt F of it reflects (Fresnel's equations for a dielectric), and
//              on total internal reflection all of it does
// When kd + ks + kr + kt exceeds 1 all four are scaled down to sum to 1. Radiance refracted into
// a denser medium is compressed by (n1/n2)^2 (Veach 1997, 5.2); importance is not, and with a
// shading normal importance scatters by the adjoint's correction (Veach 1997, 5.3).
#pragma once

#include <array>
#include <optional>

#include "glint/math/color.h"
#include "glint/math/vector.h"

namespace glint {

// What a path carries: radiance from the lights (path tracing), or importance from the camera
// (particles leaving the lights, whose BSDF is the adjoint).
enum class TransportMode { radiance, importance };

// The BSDF's parts, in the order they are picked from.
enum class BsdfLobe { diffuse, highlight, reflect, transmit };
inline constexpr int kBsdfLobeCount = 4;

// The material's numbers at one surface point, and the direction the path came from.
struct BsdfInputs {
    Vector3 wo;  // unit, away from the surface: towards the viewer (radiance) or the light
    Normal3 n;   // shading normal, unit, on wo's side
    Normal3 ng;  // geometric normal, unit, on wo's side: which side a direction leaves by
    float kd = 0;
    Color color{1, 1, 1};  // C, the surface colour the diffuse part takes
    float ks = 0, shininess = 0;
    float reflect = 0, roughness = 0;
    Color reflect_filter{1, 1, 1};  // the reflect part's own colour (a metallic reflection)
    float transmit = 0, transmit_roughness = 0;
    Color transmit_filter{1, 1, 1};  // the transmitted part's colour (coloured glass)
    float n1 = 1, n2 = 1;            // indices on wo's side and beyond (Snell's eta = n1 / n2)
    bool fresnel = false;
};

struct BsdfSample {
    Vector3 wi;          // unit, away from the surface
    Color f;             // f(wo, wi) of the parts that are not delta; 0 for a delta part
    float pdf = 0;       // per steradian over the parts that are not delta; for a delta part the
                         // probability of picking it
    Color weight;        // f |N.wi| / pdf: what a path's throughput is multiplied by
    BsdfLobe lobe;       // the part drawn from
    bool delta = false;  // a mirror or clear refraction: no other direction scatters
    bool transmitted = false;  // wi crossed the surface
};

class Bsdf {
public:
    explicit Bsdf(const BsdfInputs& in, TransportMode mode = TransportMode::radiance);

    // f(wo, wi) summed over the parts that are not delta, wi unit and away from the surface.
    Color eval(Vector3 wi) const;
    // The density per steradian that sample() draws wi with, over the parts that are not delta.
    float pdf(Vector3 wi) const;
    // A direction drawn from u_lobe (which part) and u (where in it); nothing when the part
    // drawn sends it through the surface the wrong way or the BSDF scatters nothing.
    std::optional<BsdfSample> sample(float u_lobe, Point2 u) const;
    // The delta part `lobe` (reflect or transmit) whole, not picked: pdf 1 and the weight it
    // scatters, for an integrator that follows every delta part (a ray tree) rather than one;
    // nothing when that part is not delta, scatters nothing or leaves by the wrong side.
    std::optional<BsdfSample> delta_part(BsdfLobe lobe) const;

    // Whether any part is not delta: next-event estimation can reach it.
    bool has_smooth_part() const;
    // The fraction of light the BSDF scatters in all, kd C + ks + kr + kt F_t scaled.
    Color albedo() const;
    // The probability each part is picked with, by the share of light it scatters.
    float lobe_probability(BsdfLobe lobe) const { return pick_[int(lobe)]; }

private:
    // Each part's f, for wi on the side it scatters to (0 elsewhere).
    Color diffuse_f(Vector3 wi) const;
    float highlight_f(Vector3 wi) const;
    float glossy_f(Vector3 wi, Vector3 axis, float exponent, float weight) const;
    // The part's density for wi (0 for a delta part or the wrong side).
    float lobe_pdf(BsdfLobe lobe, Vector3 wi) const;
    bool reflects(Vector3 wi) const { return dot(wi, in_.ng) > 0; }
    // For importance, the shading normal's correction of the adjoint (1 for radiance).
    float adjoint_factor(Vector3 wi) const;

    BsdfInputs in_;
    TransportMode mode_;
    Color diffuse_;    // kd C, scaled
    float highlight_;  // ks, scaled
    float reflect_;    // kr (with kt F, and all of kt on total internal reflection), scaled
    Color reflect_color_{1, 1, 1};  // its colour: kr's own filtered, what kt moved to it not
    float transmit_;     // kt (1 - F with fresnel), scaled; 0 on total internal reflection
    Vector3 mirror_;     // wo mirrored about n
    Vector3 refracted_;  // Snell's direction of wo, when transmit_ > 0
    float reflect_exponent_ = 0, transmit_exponent_ = 0;  // the glossy lobes' Phong exponents
    bool reflect_delta_ = true, transmit_delta_ = true;   // a mirror, clear refraction
    float compression_ = 1;  // (n1/n2)^2 for radiance refracted, 1 for importance
    std::array<float, kBsdfLobeCount> pick_{};
};

}  // namespace glint
