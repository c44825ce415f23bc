// Output variables (AOVs): what a render writes beside the image when asked, one layer each.
// Three kinds:
// - what the eye ray hit (depth, position, normal, albedo, uv): the filter-weighted mean over the
//   pixel's samples that hit something; 0 where none did;
// - the image's parts and the work per sample (emission ... refracted, tree depth, traversal
//   counts): the filter-weighted mean over all samples, as the image itself, so the six parts
//   add up to the image;
// - ids (object, material): those of the pixel's first sample, -1 where it missed;
// and the samples each pixel took, from the render's state.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "glint/math/color.h"
#include "glint/math/vector.h"

namespace glint {

enum class Aov : std::uint8_t {
    depth,       // distance along the eye ray to its hit
    position,    // the hit point, world space
    normal,      // the shading normal, world space, facing the eye
    albedo,      // the surface colour C (texture) at the hit
    uv,          // the surface's texture coordinates at the hit
    object,      // the scene index of the object hit
    material,    // the scene index of its material
    emission,    // light the eye ray sees directly: the surface's emission, or the background
    ambient,     // ka Ia C at the eye ray's hit
    diffuse,     // the lights' diffuse terms there, shadowed
    specular,    // the lights' highlight terms there, shadowed
    reflected,   // kr I(reflected): the reflected branch of the ray tree
    refracted,   // kt I(refracted): the refracted branch
    direct,      // path tracing: light that reaches the eye ray's hit straight from an emitter
    indirect,    // path tracing: light that reaches it after scattering on the way
    fog,         // the light the fog adds along the eye ray (the other parts arrive through it)
    tree_depth,  // the depth of the sample's ray tree (1: the eye ray alone)
    samples,     // samples the pixel took
    nodes,       // acceleration-structure nodes visited, by all the sample's rays
    primitives,  // primitives tested for a hit, by all the sample's rays
};
inline constexpr std::size_t kAovCount = 20;

enum class AovKind : std::uint8_t { surface, sample_mean, id, pixel };

struct AovInfo {
    std::string_view name;  // as --aov takes it and as the EXR layer is named
    AovKind kind;
    int channels;                             // 1, 2 or 3
    std::array<std::string_view, 3> channel;  // the EXR channels' names within the layer
    std::string_view description;
};

const AovInfo& aov_info(Aov aov);

// Whether this build counts traversal steps (the nodes and primitives variables): the counters
// cost renders a few percent, so a release build leaves them out unless configured with
// -DGLINT_TRAVERSAL_COUNTERS=ON.
bool counts_traversal();

class AovSet {
public:
    bool has(Aov a) const { return (bits_ >> unsigned(a)) & 1u; }
    void add(Aov a) { bits_ |= 1u << unsigned(a); }
    bool empty() const { return bits_ == 0; }
    std::vector<Aov> list() const;  // in Aov order
    bool operator==(const AovSet&) const = default;

private:
    std::uint32_t bits_ = 0;
};

// "depth,normal,contributions": names of aov_info, and the groups `contributions` (emission to
// fog), `surface` (depth to uv), `ids`, `cost` (nodes, primitives) and `all`. Throws
// std::invalid_argument naming an unknown or unavailable name.
AovSet parse_aov_list(std::string_view list);

// One sample's output variables, as the AovRecorder gathers them.
struct AovSample {
    bool hit = false;
    float depth = 0;
    Point3 position;
    Vector3 normal;
    Color albedo;
    Point2 uv;
    std::int32_t object = -1, material = -1;
    Color emission, ambient, diffuse, specular, reflected, refracted, direct, indirect, fog;
    int tree_depth = 0;
    std::uint64_t nodes = 0, primitives = 0;

    // The variable as a colour: scalars in every channel, uv in r and g.
    Color value(Aov a) const;
};

}  // namespace glint
