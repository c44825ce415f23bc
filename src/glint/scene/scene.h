// The scene as plain data, as every loader produces it: settings, camera, materials, lights
// and objects. It knows nothing of how it will be rendered.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "glint/camera/camera_spec.h"
#include "glint/geometry/shape.h"
#include "glint/image/image_limits.h"  // kMaxImagePixels, shared with image files
#include "glint/math/color.h"
#include "glint/math/huge_page_allocator.h"
#include "glint/sampling/pixel_sampler.h"
#include "glint/shading/light.h"
#include "glint/shading/material.h"

namespace glint {

// What the scene asks of the image and of the ray tree.
struct RenderSettings {
    int width = 640;
    int height = 480;
    int samples_per_pixel = 1;
    SamplerKind sampler = SamplerKind::regular;
    int max_depth = 5;          // eye rays are depth 1; rays deeper than this are not traced
    float min_weight = 0.001f;  // rays whose product of weights falls below this are not traced
    Color background;           // what rays that hit nothing see
    // Shadow feelers pass through transparent objects, attenuated by their transmit weight,
    // instead of stopping at them.
    bool transparent_shadows = false;
};

struct SceneObject {
    Shape shape;
    std::uint32_t material = 0;  // index into Scene::materials
    bool casts_shadow = true;
};

struct Scene {
    RenderSettings settings;
    CameraSpec camera;
    Color ambient;  // Ia, the global ambient light
    std::vector<Material> materials;
    std::vector<Light> lights;
    LargeVector<SceneObject> objects;
    // What the loader accepted but the user should know ("3 degenerate triangles dropped").
    std::vector<std::string> warnings;
};

// Limits checked before memory is taken, so that an absurd scene is an error, not an outage.
inline constexpr int kMaxImageSide = 65536;
inline constexpr int kMaxSamplesPerPixel = 65536;
inline constexpr int kMaxDepth = 64;

}  // namespace glint
