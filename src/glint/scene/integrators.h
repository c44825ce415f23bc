// The integrators, the algorithms of the slides that turn an eye ray into a colour, as one table:
// name, the sampler and filter each takes unless the scene says otherwise, whether it reads
// materials as physically based scattering, and what it computes in a line. The loaders, the
// command line, `glint info` and the docs read it; render/integrators/integrator_family.h turns
// a kind into its class.
#pragma once

#include <optional>
#include <span>
#include <string_view>

#include "glint/sampling/filter.h"
#include "glint/sampling/sampler.h"

namespace glint {

enum class IntegratorKind { whitted, distributed, path, light, photon, cone, beam };

struct IntegratorInfo {
    IntegratorKind kind;
    std::string_view name;  // as scene files and the command line write it
    SamplerKind sampler;    // the sampler it takes when the scene names none
    FilterSpec filter;      // the filter likewise
    // Reads materials as scattering functions and lights as radiometric sources, and so
    // ignores the ambient term (Whitted's stand-in for the light it computes).
    bool physically_based;
    // Traces particles from the lights too, whose light lands anywhere on the film.
    bool traces_particles;
    // The samples of each pixel a pass takes when it must be a given number (the photon
    // integrator builds a photon map for each sample index); 0: the render loop's choice.
    int pass_size;
    std::string_view summary;  // one line: who, when, what
};

// Every integrator, sorted by name.
std::span<const IntegratorInfo> integrator_infos();
const IntegratorInfo& integrator_info(IntegratorKind kind);

// The integrators' names, sorted, as scene files and the command line write them.
std::span<const std::string_view> integrator_names();
std::optional<IntegratorKind> integrator_from_name(std::string_view name);
std::string_view integrator_name(IntegratorKind kind);

// Whether the integrator's samples are rays, which `explain` and the output variables follow:
// the cone and beam integrators trace cones and beams.
bool traces_rays(IntegratorKind kind);

}  // namespace glint
