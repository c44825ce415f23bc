// The integrators' table.
#include "glint/scene/integrators.h"

#include <array>

namespace glint {

namespace {

// Sorted by name, for the messages that list them.
constexpr IntegratorInfo kIntegrators[] = {
    // Exact coverage of each pixel: a box of one pixel, the area it covers.
    {IntegratorKind::beam, "beam", SamplerKind::regular, FilterSpec{}, false, false, 0,
     "Heckbert and Hanrahan's beam tracing (1984), for planar polygons: the view pyramid swept "
     "through the scene as beams, polygons clipped from them front to back, mirrors and glass "
     "starting new beams; each pixel drawn from the exact areas of the beam tree's fragments"},
    // One cone a pixel through its centre, its own anti-aliasing: no filter beyond the pixel.
    {IntegratorKind::cone, "cone", SamplerKind::regular, FilterSpec{}, false, false, 0,
     "Amanatides' cone tracing (1984): a cone a pixel, as wide as the pixel, each shape "
     "covering a fraction of it blended front to back; shadows by cones to the lights, glossy "
     "reflection by cones widened with roughness"},
    {IntegratorKind::distributed, "distributed", SamplerKind::jittered,
     // The notes' "stochastic sampling with Gaussian weighting".
     FilterSpec{FilterKind::gaussian, 1.5f}, false, false, 0,
     "Cook, Porter and Carpenter's distributed ray tracing (1984): Whitted's ray tree with each "
     "ray spread over what it integrates (soft shadows, glossy reflection, depth of field, "
     "motion blur, dispersion)"},
    {IntegratorKind::light, "light", SamplerKind::sobol, FilterSpec{FilterKind::gaussian, 1.5f},
     true, true, 0,
     "the notes' backward ray tracing (light tracing, Arvo 1986; Dutre et al. 1993): particles "
     "leave the lights, scatter, and each surface they reach is connected to the eye"},
    {IntegratorKind::path, "path", SamplerKind::sobol, FilterSpec{FilterKind::gaussian, 1.5f}, true,
     false, 0,
     "Kajiya's path tracing (1986) with next-event estimation and multiple importance sampling: "
     "global illumination, light reflected from surface to surface (colour bleeding)"},
    {IntegratorKind::photon, "photon", SamplerKind::sobol, FilterSpec{FilterKind::gaussian, 1.5f},
     true, false, 1,
     "progressive photon mapping (Jensen 1996; Knaus and Zwicker 2011): a photon map a pass, "
     "its gathering radius shrinking pass by pass, for caustics and colour bleeding"},
    {IntegratorKind::whitted, "whitted", SamplerKind::regular, FilterSpec{}, false, false, 0,
     "Whitted's recursive ray tracing (1980): Phong's local term with shadow feelers, and the "
     "mirror-reflected and refracted rays"},
};

constexpr std::array<std::string_view, std::size(kIntegrators)> names_of() {
    std::array<std::string_view, std::size(kIntegrators)> names{};
    for (std::size_t i = 0; i < names.size(); ++i) names[i] = kIntegrators[i].name;
    return names;
}
constexpr auto kNames = names_of();

}  // namespace

std::span<const IntegratorInfo> integrator_infos() { return kIntegrators; }

const IntegratorInfo& integrator_info(IntegratorKind kind) {
    for (const IntegratorInfo& info : kIntegrators)
        if (info.kind == kind) return info;
    return kIntegrators[0];  // every kind has a row (integrators_test.cpp)
}

std::span<const std::string_view> integrator_names() { return kNames; }

std::optional<IntegratorKind> integrator_from_name(std::string_view name) {
    for (const IntegratorInfo& info : kIntegrators)
        if (info.name == name) return info.kind;
    return std::nullopt;
}

std::string_view integrator_name(IntegratorKind kind) { return integrator_info(kind).name; }

bool traces_rays(IntegratorKind kind) {
    return kind != IntegratorKind::cone && kind != IntegratorKind::beam;
}

}  // namespace glint
