// The BSDF's parts: evaluated, their densities summed by the probability each is picked with
// (so that multiple importance sampling sees the density sample() really draws with), and drawn.
#include "glint/shading/bsdf.h"

#include <algorithm>
#include <cmath>

#include "glint/math/constants.h"
#include "glint/sampling/warp.h"
#include "glint/shading/optics.h"
#include "glint/shading/roughness.h"

namespace glint {

Bsdf::Bsdf(const BsdfInputs& in, TransportMode mode) : in_(in), mode_(mode) {
    const float sum = in.kd + in.ks + in.reflect + in.transmit;
    const float scale = sum > 1 ? 1 / sum : 1;
    diffuse_ = in.kd * scale * in.color;
    highlight_ = in.ks * scale;
    reflect_ = in.reflect * scale;
    transmit_ = in.transmit * scale;
    const float cos_o = std::max(0.0f, dot(in.wo, in.n));
    mirror_ = normalize(2 * cos_o * to_vector(in.n) - in.wo);
    if (transmit_ > 0) {
        const float eta = in.n1 / in.n2;
        if (const auto t = refract(-in.wo, in.n, eta)) {
            refracted_ = normalize(*t);
            const float reflected = in.fresnel ? transmit_ * fresnel_dielectric(cos_o, eta) : 0;
            reflect_ += reflected;
            transmit_ -= reflected;
        } else {  // total internal reflection
            reflect_ += transmit_;
            transmit_ = 0;
        }
        if (mode == TransportMode::radiance) compression_ = eta * eta;
    }
    if (in.reflect_filter != Color{1, 1, 1} && reflect_ > 0) {
        const float own = in.reflect * scale;
        reflect_color_ = (own * in.reflect_filter + Color::gray(reflect_ - own)) / reflect_;
    }
    reflect_delta_ = in.roughness < kMirrorRoughness;
    if (!reflect_delta_) reflect_exponent_ = phong_exponent_of_roughness(in.roughness);
    transmit_delta_ = in.transmit_roughness < kMirrorRoughness;
    if (!transmit_delta_) transmit_exponent_ = phong_exponent_of_roughness(in.transmit_roughness);
    // Each part by the share of light it scatters: the diffuse colour by its mean.
    pick_ = {mean(diffuse_), highlight_, reflect_, transmit_};
    float total = 0;
    for (const float w : pick_) total += w;
    if (total > 0)
        for (float& w : pick_) w /= total;
}

bool Bsdf::has_smooth_part() const {
    return pick_[int(BsdfLobe::diffuse)] > 0 || pick_[int(BsdfLobe::highlight)] > 0 ||
           (pick_[int(BsdfLobe::reflect)] > 0 && !reflect_delta_) ||
           (pick_[int(BsdfLobe::transmit)] > 0 && !transmit_delta_);
}

Color Bsdf::albedo() const {
    return diffuse_ + Color::gray(highlight_) + reflect_ * reflect_color_ +
           transmit_ * in_.transmit_filter;
}

Color Bsdf::diffuse_f(Vector3 wi) const {
    if (!reflects(wi)) return {};
    return diffuse_ * (1 / kPi);
}

float Bsdf::highlight_f(Vector3 wi) const {
    if (highlight_ <= 0 || !reflects(wi)) return 0;
    const float c = dot(mirror_, wi);
    if (c <= 0) return 0;
    const float n = in_.shininess;
    return highlight_ * (n + 2) / (2 * kPi) * std::pow(c, n);
}

// The lobe's density over the cosine at the end the path leaves by: wi for radiance (so that a
// sample weighs `weight`, as Cook's glossy rays do), wo for its adjoint.
float Bsdf::glossy_f(Vector3 wi, Vector3 axis, float exponent, float weight) const {
    const float c = dot(axis, wi);
    if (weight <= 0 || c <= 0) return 0;
    const float cos_end =
        std::abs(dot(mode_ == TransportMode::radiance ? wi : in_.wo, to_vector(in_.n)));
    if (!(cos_end > 0)) return 0;
    return weight * phong_lobe_pdf(c, exponent) / cos_end;
}

// Veach (1997, 5.3): with a shading normal the adjoint BSDF is not the BSDF with its directions
// swapped; importance scatters by f(wi, wo) |wo.ns| |wi.ng| / (|wo.ng| |wi.ns|), so that
// particles light a smooth-shaded surface as the eye's paths find it lit.
float Bsdf::adjoint_factor(Vector3 wi) const {
    const Normal3 &ns = in_.n, &ng = in_.ng;
    if (mode_ == TransportMode::radiance || (ns.x == ng.x && ns.y == ng.y && ns.z == ng.z))
        return 1;
    const float below = std::abs(dot(in_.wo, to_vector(ng))) * std::abs(dot(wi, to_vector(ns)));
    if (!(below > 0)) return 0;
    return std::abs(dot(in_.wo, to_vector(ns))) * std::abs(dot(wi, to_vector(ng))) / below;
}

Color Bsdf::eval(Vector3 wi) const {
    if (reflects(wi)) {
        Color f = diffuse_f(wi) + Color::gray(highlight_f(wi));
        if (!reflect_delta_)
            f += reflect_color_ * glossy_f(wi, mirror_, reflect_exponent_, reflect_);
        return f * adjoint_factor(wi);
    }
    if (transmit_delta_) return {};
    return in_.transmit_filter * (glossy_f(wi, refracted_, transmit_exponent_, transmit_) *
                                  compression_ * adjoint_factor(wi));
}

float Bsdf::lobe_pdf(BsdfLobe lobe, Vector3 wi) const {
    switch (lobe) {
        case BsdfLobe::diffuse:
            return reflects(wi) ? std::max(0.0f, dot(to_vector(in_.n), wi)) / kPi : 0;
        case BsdfLobe::highlight:
            return reflects(wi) ? phong_lobe_pdf(dot(mirror_, wi), in_.shininess) : 0;
        case BsdfLobe::reflect:
            if (reflect_delta_ || !reflects(wi)) return 0;
            return phong_lobe_pdf(dot(mirror_, wi), reflect_exponent_);
        case BsdfLobe::transmit:
            if (transmit_delta_ || reflects(wi)) return 0;
            return phong_lobe_pdf(dot(refracted_, wi), transmit_exponent_);
    }
    return 0;
}

float Bsdf::pdf(Vector3 wi) const {
    float p = 0;
    for (int l = 0; l < kBsdfLobeCount; ++l)
        if (pick_[l] > 0) p += pick_[l] * lobe_pdf(BsdfLobe(l), wi);
    return p;
}

std::optional<BsdfSample> Bsdf::sample(float u_lobe, Point2 u) const {
    int l = 0;
    float below = 0;
    for (; l < kBsdfLobeCount - 1; ++l) {
        if (u_lobe < below + pick_[l] && pick_[l] > 0) break;
        below += pick_[l];
    }
    if (!(pick_[l] > 0)) return std::nullopt;  // scatters nothing, or u_lobe rounded past it
    BsdfSample s;
    s.lobe = BsdfLobe(l);
    if ((s.lobe == BsdfLobe::reflect && reflect_delta_) ||
        (s.lobe == BsdfLobe::transmit && transmit_delta_)) {
        // The part whole, weighed by how seldom it is picked.
        std::optional<BsdfSample> part = delta_part(s.lobe);
        if (part) {
            part->pdf = pick_[l];
            part->weight *= 1 / pick_[l];
        }
        return part;
    }
    switch (s.lobe) {
        case BsdfLobe::diffuse:
            s.wi = from_frame(sample_phong_lobe(u, 1), to_vector(in_.n));  // cosine-weighted
            break;
        case BsdfLobe::highlight:
            s.wi = from_frame(sample_phong_lobe(u, in_.shininess), mirror_);
            break;
        case BsdfLobe::reflect:
            s.wi = from_frame(sample_phong_lobe(u, reflect_exponent_), mirror_);
            break;
        case BsdfLobe::transmit:
            s.wi = from_frame(sample_phong_lobe(u, transmit_exponent_), refracted_);
            break;
    }
    s.transmitted = s.lobe == BsdfLobe::transmit;
    // A direction on the wrong side of the surface scatters nothing.
    if (reflects(s.wi) == s.transmitted) return std::nullopt;
    s.f = eval(s.wi);
    s.pdf = pdf(s.wi);
    if (!(s.pdf > 0)) return std::nullopt;
    s.weight = s.f * (std::abs(dot(to_vector(in_.n), s.wi)) / s.pdf);
    return s;
}

std::optional<BsdfSample> Bsdf::delta_part(BsdfLobe lobe) const {
    const bool transmitted = lobe == BsdfLobe::transmit;
    if (!transmitted && lobe != BsdfLobe::reflect) return std::nullopt;
    if (!(pick_[int(lobe)] > 0) || !(transmitted ? transmit_delta_ : reflect_delta_))
        return std::nullopt;
    BsdfSample s;
    s.lobe = lobe;
    s.wi = transmitted ? refracted_ : mirror_;
    s.transmitted = transmitted;
    if (reflects(s.wi) == transmitted) return std::nullopt;
    s.delta = true;
    s.pdf = 1;
    const float w = transmitted ? transmit_ * compression_ : reflect_;
    s.weight = Color::gray(w * adjoint_factor(s.wi));
    s.weight *= transmitted ? in_.transmit_filter : reflect_color_;
    return s;
}

}  // namespace glint
