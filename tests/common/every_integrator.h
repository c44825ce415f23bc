// Small scenes, one for each integrator and the films that behave differently: the one-pixel box
// (Whitted's film, float sums), a Gaussian reaching across tiles, adaptive sampling, particles
// splatted anywhere (light), a photon map a pass (photon), cones and beams. For the tests that
// split a render and check it adds up to one process's.
#pragma once

#include <cstring>
#include <string>
#include <vector>

#include "glint/image/image.h"
#include "glint/render/render.h"
#include "glint/scene/yaml/yaml_scene_loader.h"

namespace glint::testing {

struct IntegratorCase {
    std::string name;
    Scene scene;
};

inline Scene load_small(const std::string& file, int width, int height, int spp) {
    Scene scene = load_yaml_scene(std::string(GLINT_SOURCE_DIR) + "/scenes/" + file);
    scene.settings.width = width;
    scene.settings.height = height;
    scene.settings.samples_per_pixel = spp;
    return scene;
}

inline std::vector<IntegratorCase> every_integrator() {
    std::vector<IntegratorCase> all;
    all.push_back({"whitted", load_small("showcase.yaml", 40, 30, 9)});
    Scene distributed = load_small("distributed-showcase.yaml", 40, 24, 8);
    all.push_back({"distributed", distributed});
    Scene adaptive = distributed;
    adaptive.settings.samples_per_pixel = 24;
    adaptive.settings.adaptive = AdaptiveSampling{0.05f, 4};
    all.push_back({"distributed adaptive", adaptive});
    for (const IntegratorKind kind :
         {IntegratorKind::path, IntegratorKind::light, IntegratorKind::photon}) {
        Scene scene = load_small("features/cornell-box.yaml", 24, 24, 6);
        scene.settings.integrator = kind;
        scene.settings.photons.per_pass = 2000;
        all.push_back({std::string(integrator_name(kind)), scene});
    }
    all.push_back({"cone", load_small("features/cone-tracing.yaml", 32, 24, 4)});
    all.push_back({"beam", load_small("features/beam-tracing.yaml", 32, 24, 4)});
    return all;
}

// Small tiles and passes, so that a small image has many pieces to split.
inline RenderOptions small_pieces(int threads = 0) {
    RenderOptions o;
    o.threads = threads;
    o.tile_size = 8;
    o.pass_size = 2;
    o.seed = 11;
    o.record_samples_taken = true;
    return o;
}

inline bool same_bits(const Image& a, const Image& b) {
    return a.width == b.width && a.height == b.height &&
           std::memcmp(a.pixels.data(), b.pixels.data(), a.pixels.size() * sizeof(Color)) == 0;
}

}  // namespace glint::testing
