// The ray tree of one pixel sample as the integrators computed it (`glint explain`): each ray's
// hit, the local terms with their numbers light by light, the branches with their weights and
// Snell's law, the random numbers drawn, and the exact colour each ray brought back, from which
// the sample's colour is recomputed to the last bit.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "glint/math/color.h"
#include "glint/math/ray.h"
#include "glint/math/vector.h"
#include "glint/render/pencil.h"
#include "glint/render/ray_stats.h"
#include "glint/shading/fog.h"

namespace glint {

// Why a ray, or a branch of it, was not followed further.
enum class StopReason : std::uint8_t {
    none,
    missed,                     // the ray hit nothing: it brings the background
    max_depth,                  // the ray tree's deepest level: no reflected or refracted rays
    min_weight,                 // the branch's weight (product of kr and kt) is below the minimum
    blocked_by_surface,         // the glossy lobe tipped the ray through the surface
    total_internal_reflection,  // no refracted ray: its weight went to the reflected one
    roulette,                   // the path ended by Russian roulette
};
std::string_view stop_reason_name(StopReason reason);

// A number or pair of numbers the camera drew for a sample, and what for ("pixel", "lens", "time").
struct RandomDraw {
    std::string purpose;
    std::uint32_t dimension;
    Point2 u;  // u.y is 0 for a one-dimensional draw
    bool pair = true;
};

// One light sample at a surface point: the shadow feeler and Phong's terms for it.
struct LightSampleRecord {
    int index = 0;             // j of the light's n samples
    std::optional<Point2> u;   // the numbers that chose the point on an area light
    Vector3 to_light;          // L
    float distance = 0;        // to the light (infinite for a directional light)
    Color intensity;           // I_L arriving, attenuated
    float n_dot_l = 0;         // N.L with the shading normal
    bool faces_light = false;  // N.L > 0 and the light sends something: a feeler was traced
    Color shadow{1, 1, 1};     // the feeler's transmittance per channel: 1 lit, 0 shadowed
    bool shadow_map = false;   // the shadow was looked up in the light's map (shadows: map)
    std::optional<std::uint32_t> occluder;  // the first object in the way, when shadowed
    bool blinn = true;                      // the highlight is Blinn's (H.N), else Phong's (R.V)
    Vector3 highlight_vector;               // H or R
    float highlight_cosine = 0;             // H.N or R.V before the exponent
    float brilliance = 1;                   // b of (N.L)^b
    float metallic = 0;                     // the highlight's colour S: white to C
    Color diffuse;                          // shadow IL kd C (N.L)^b
    Color highlight;                        // shadow IL ks S spec^n
    Color term;                             // what the integrator added: exactly its value
};

// A light's share of a surface point's local term: one sample, or the mean of n.
struct LightRecord {
    std::string name;           // "point light 0", "area light 1 (disk)", "emitting object 4"
    std::size_t light = 0;      // index of World::lights(), or of object_lights()
    bool object_light = false;  // an emitting object sampled over its area
    bool averaged = false;      // value is the samples' sum over their count
    std::vector<LightSampleRecord> samples;
    Color value;  // exactly what the integrator added for this light
};

// A reflected or refracted ray a surface point sends, or would have sent.
struct BranchRecord {
    RayKind kind = RayKind::reflected;
    float k = 0;                         // kr or kt at the point (after total internal reflection)
    Color factor;                        // what the child's colour is multiplied by (k, dispersed)
    std::optional<Point2> lobe_u;        // the numbers that spread it over a glossy lobe
    StopReason stop = StopReason::none;  // none: traced
    float survival = 1;  // Russian roulette's probability of tracing it (the photon integrator)
    int child = -1;      // index of the traced ray's node
};

// What the path tracer did at one surface point: the emission it counted and how it weighed
// it, the one light it sampled (next-event estimation), and the direction it scattered in.
// One light's sample by next-event estimation.
struct NextEventRecord {
    std::string light;      // its name, as LightRecord's
    float pick = 0;         // the probability the light was picked with, by power (1: every light)
    Vector3 to_light;       // L
    float distance = 0;     // to the point on the light (infinite for a directional one)
    Color irradiance;       // pi I_L: what a surface facing the light receives from it
    Color f;                // the BSDF for L
    float cosine = 0;       // |N.L|
    float light_pdf = 0;    // per steradian, 0 for lights no scattered ray can hit
    float bsdf_pdf = 0;     // the BSDF's density for L
    float mis = 1;          // the power heuristic's weight of the light sample
    Color shadow{1, 1, 1};  // the feeler: 1 unblocked, 0 blocked
    Color term;             // f |N.L| pi I_L shadow mis / pick: exactly what it added
};

struct PathVertexRecord {
    Color le;                      // the surface's emission
    float emission_weight = 1;     // the MIS weight Le counts with: 1 when seen by the eye or
                                   // after a delta part, 0 when it only glows
    float emission_bsdf_pdf = 0;   // the densities weighed: of the direction that found it,
    float emission_light_pdf = 0;  // and of a shadow ray finding it (0: no light samples it)
    // Next-event estimation: the light picked, or every light, in the order added.
    std::vector<NextEventRecord> next_events;
    // The photon integrator's gathering: the photons found within the radius (-1: none
    // gathered here) and their estimate, exactly what it added.
    int photons = -1;
    float gather_radius = 0;
    Color photon_term;
    // Scattering.
    bool scattered = false;
    std::string lobe;  // "diffuse", "highlight", "reflect", "transmit"
    Vector3 wi;
    Color scatter_f;        // 0 for a delta part
    float scatter_pdf = 0;  // per steradian, or the part's probability for a delta one
    bool delta = false;
    Color weight;        // f |N.wi| / pdf
    float survival = 1;  // Russian roulette's probability that the path goes on
};

struct RayNode {
    RayKind kind = RayKind::primary;
    int parent = -1;
    int depth = 1;
    float weight = 1;           // product of kr and kt above: the ray-tree cut's measure
    Color throughput{1, 1, 1};  // product of the branch factors above: this ray's colour's share
    Ray ray;
    StopReason stop = StopReason::none;  // missed or max_depth; none for a ray that branched
    // The hit (when not missed).
    float t = 0;
    std::uint32_t object = 0;
    std::optional<std::uint32_t> triangle;  // of a mesh, its index in the mesh
    std::string shape, material;
    Point3 point;
    Vector3 geometric_normal, shading_normal;  // turned towards the ray
    bool entering = false;                     // met the front (outward) side
    // The ray's pencil where it meets the surface (pencil.h); none when it carries none (past a
    // rough surface, or a shape that does not say how its normal bends).
    std::optional<PencilAtSurface> pencil;
    // A dispersive surface's refracted ray takes one wavelength (nm), drawn from u.
    std::optional<float> wavelength, wavelength_u;
    Color background;  // what a missed ray brings
    Color emission, ambient;
    std::vector<LightRecord> lights;
    Color direct;  // the lights' sum (the colour adds each light's value in turn)
    // Snell's law at a transmitting surface.
    bool transmits = false;
    float n1 = 1, n2 = 1, cos_incident = 0, cos_refracted = 0;
    bool total_internal_reflection = false;
    std::vector<BranchRecord> branches;
    std::optional<PathVertexRecord> path;  // the path tracer's numbers at the point
    // The fog between the ray's origin and its end: the ray brings back T x (its terms and
    // branches) + the fog's own light.
    std::optional<FogEffect> fog;
    bool fog_inside = false;  // the fog is the interior fade of the object the ray is inside
    Color value;              // exactly what the ray brought back
};

// A particle of the light integrator that landed on the explained pixel.
struct ParticleContribution {
    int from_x = 0, from_y = 0;  // the pixel whose sample sent it
    std::size_t emitter = 0;     // of the emitters, lights then emitting objects then the sky
    std::string light;           // the emitter's name, as LightRecord's ("the sky")
    int bounces = 0;             // surfaces it met before the one joined to the eye
    std::uint32_t object = 0;    // that surface
    Point3 point;
    Point2 film;       // where the eye sees the point, in pixels
    Color value;       // what it sends to the eye, before the film's filter
    float weight = 0;  // its weight in the pixel: the filter's there, over the particles a pixel
};

// The light integrator's particles of one sample pass (one sent by each pixel's sample) and what
// they bring to the explained pixel: the part of its colour its own eye ray cannot find.
struct ParticleReport {
    std::uint64_t traced = 0;  // particles sent
    std::uint64_t seen = 0;    // of them, those joined to the eye somewhere on the film
    std::uint64_t landed = 0;  // contributions (a particle may add one a bounce) on this pixel
    Color value;               // their sum, each times its weight: the pass's particle share
    std::vector<ParticleContribution> largest;  // the largest few, largest first
};

struct RayTree {
    int x = 0, y = 0, sample = 0;
    std::uint64_t seed = 0;
    std::string integrator;
    Point2 film;  // where the sample lands, in pixels
    // Under filter importance sampling (adaptive sampling): the sample's weight in its own pixel,
    // which alone it counts for.
    std::optional<float> filter_weight;
    std::vector<RandomDraw> draws;  // the camera's: pixel, lens, time
    std::vector<RayNode> nodes;     // nodes[0] is the eye ray, children after their parents
    Color sample_value;             // what the integrator returned for the sample
    // The light integrator's particles on the pixel, which come besides the sample's value.
    std::optional<ParticleReport> particles;
};

// The sample's colour worked out again from the tree's recorded terms, combined as the
// integrators combine them (emission + ambient, plus each light's value in turn, plus each traced
// branch's factor times its colour): equal to sample_value to the last bit.
Color evaluate(const RayTree& tree);
// The same for one node: its local terms and its children's colours times their factors.
Color evaluate(const RayTree& tree, int node);

// A node's own terms (emission, ambient and lights, seen through its fog, and the fog's own
// light) times its throughput: its share of the sample; over the whole tree these add up to the
// sample (up to rounding).
Color contribution(const RayNode& node);

}  // namespace glint
