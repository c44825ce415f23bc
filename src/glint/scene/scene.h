// The scene as plain data, as every loader produces it: settings, camera, materials, lights
// and objects. It knows nothing of how it will be rendered.
#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "glint/camera/camera_spec.h"
#include "glint/geometry/shape.h"
#include "glint/math/animated_transform.h"
#include "glint/math/color.h"
#include "glint/math/huge_page_allocator.h"
#include "glint/sampling/filter.h"
#include "glint/sampling/sampler.h"
#include "glint/scene/integrators.h"
#include "glint/scene/scene_limits.h"
#include "glint/scene/working_space.h"
#include "glint/shading/fog.h"
#include "glint/shading/light.h"
#include "glint/shading/material.h"
#include "glint/shading/sky.h"

namespace glint {

// What the scene asks of the image and of the ray tree.
// Adaptive sampling: a pixel takes samples until its error estimate falls below the threshold,
// at least min_samples and at most RenderSettings::samples_per_pixel.
struct AdaptiveSampling {
    // The pixel's relative error: the 95% confidence half-width of its mean luminance,
    // 1.96 * standard error, over max(mean, kAdaptiveDarkLevel).
    float threshold = 0.02f;
    int min_samples = 16;  // >= 2: the variance needs two
};
// Darker pixels than this are judged by their absolute error, as if this bright: their noise
// cannot be seen against a relative threshold.
inline constexpr float kAdaptiveDarkLevel = 0.05f;

// The photon integrator's photon maps: one of per_pass photons for each sample index, gathered
// within a radius that starts at `radius` (0: a fiftieth of the scene's bounding sphere) and
// shrinks pass by pass as r_{i+1}^2 = r_i^2 (i + alpha) / (i + 1) (Knaus and Zwicker 2011).
struct PhotonSettings {
    int per_pass = 100000;
    float radius = 0;
    float alpha = 2.0f / 3;
    bool operator==(const PhotonSettings&) const = default;
};

// How Whitted's and Cook's ray tracers find shadows from the scene's lights: shadow feelers (the
// notes' rays towards each light), or shadow maps (Williams 1978) looked up instead.
enum class ShadowMethod { feelers, map };
inline constexpr std::string_view kShadowMethodNames[] = {"feelers", "map"};  // by ShadowMethod

struct ShadowMapSettings {
    int resolution = 512;  // texels along each edge of each face
    // In texels at the receiver: how far the receiver is moved off its surface along its
    // normal, and how much nearer than it the stored depth must be to shadow it.
    float bias = 1.5f;
    int filter = 3;  // the filter's width in texels (odd; 1: one bilinear lookup)
    bool operator==(const ShadowMapSettings&) const = default;
};

// Next-event estimation of the path and photon integrators: at each surface, one light picked
// in proportion to its power, or every light with one shadow ray each.
enum class NextEventStrategy { one, all };

struct RenderSettings {
    int width = 640;
    int height = 480;
    IntegratorKind integrator = IntegratorKind::whitted;
    int samples_per_pixel = 1;
    // Unset: the integrator's own choice (sampler_of, filter_of).
    std::optional<SamplerKind> sampler;
    std::optional<FilterSpec> filter;
    int max_depth = 5;          // eye rays are depth 1; rays deeper than this are not traced
    float min_weight = 0.001f;  // rays whose product of weights falls below this are not traced
    Color background;           // what rays that hit nothing see
    // Shadow feelers pass through transparent objects, attenuated by their transmit, tint and fade,
    // instead of stopping at them.
    bool transparent_shadows = false;
    // Shadow rays each sample sends to each area light and emitting object (distributed).
    int shadow_rays = 1;
    // Unset: every pixel takes samples_per_pixel samples.
    std::optional<AdaptiveSampling> adaptive;
    PhotonSettings photons;  // the photon integrator's
    NextEventStrategy next_event = NextEventStrategy::one;
    ShadowMethod shadows = ShadowMethod::feelers;
    ShadowMapSettings shadow_map;  // with shadows: map
    WorkingSpace working_space;
};

// The sampler and filter a render uses: the scene's, or its integrator's default (whitted: the
// regular grid and a box over each pixel, its samples averaged; distributed: jittered samples
// and a Gaussian; adaptive sampling: Sobol points).
SamplerKind sampler_of(const RenderSettings& settings);
FilterSpec filter_of(const RenderSettings& settings);

// A scene with frames: frame f (from 0) shows the scene at the moment f / fps, the camera's
// shutter an interval from it (scene/animation.h).
struct Animation {
    int frames = 1;
    float fps = 24;
};

// A light that moves from frame to frame: at_rest as the file gives it, placed at a moment by its
// keyframes' transform then (place_lights in scene/animation.h).
struct MovingLight {
    std::uint32_t index = 0;  // into Scene::lights
    Light at_rest;
    std::shared_ptr<const AnimatedTransform> motion;
};

struct SceneObject {
    Shape shape;
    std::uint32_t material = 0;  // index into Scene::materials
    bool casts_shadow = true;
    // With an emitting material: whether the object lights the scene (an ObjectLight, for the
    // integrators that sample areas). Off for the visible face of an area light, which is lit by
    // its Light already.
    bool emits_light = true;
};

// A place in a scene file: 1-based line and column (bytes); 0 when unknown.
struct TextPosition {
    int line = 0;
    int column = 0;
};

// Where the loader read each material, light and object, for messages about a loaded scene
// (`glint info`'s warnings). The YAML loader keeps one position a material, light and object
// (a mesh file's parts and materials at its object, an area light's face at its light; the
// built-in default material at none); other loaders keep none, and the lists stay empty.
struct SceneSources {
    std::string file;
    std::vector<TextPosition> materials, lights;
    LargeVector<TextPosition> objects;
    // The image settings only some integrators read, where the file gives them.
    std::optional<TextPosition> photons, next_event;
    // Every file the scene read besides its own (meshes, material libraries, glTF buffers,
    // textures), resolved, in the order first read; filled by load_scene.
    std::vector<std::filesystem::path> files_read;
};

struct Scene {
    RenderSettings settings;
    CameraSpec camera;
    Color ambient;  // Ia, the global ambient light
    std::vector<Material> materials;
    std::vector<Light> lights;
    LargeVector<SceneObject> objects;
    // An image round the scene in place of settings.background.
    std::optional<SkyImage> sky;
    // Fog between the surfaces, seen by the rays that carry light to the eye.
    std::vector<Fog> fogs;
    // Participating media filling the space outside objects (and inside hollow ones).
    std::vector<Medium> atmosphere;
    std::optional<Animation> animation;      // none: a still
    std::vector<MovingLight> moving_lights;  // placed at the shutter's opening
    // What the loader accepted but the user should know ("3 degenerate triangles dropped").
    std::vector<std::string> warnings;
    SceneSources sources;
};

}  // namespace glint
