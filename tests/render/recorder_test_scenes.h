// The example scenes the integrators' recorders (glint explain, the output variables) are tested
// on, between them every feature of the integrators, and a test name for each:
// "scenes/features/soft-shadows.yaml" is soft_shadows.
#pragma once

#include <gtest/gtest.h>

#include <string>

namespace glint::testing {

inline constexpr const char* kRecorderTestScenes[] = {
    "scenes/showcase.yaml",
    "scenes/whitted-basics.yaml",
    "scenes/distributed-showcase.yaml",
    "scenes/features/soft-shadows.yaml",
    "scenes/features/glossy.yaml",
    "scenes/features/translucency.yaml",
    "scenes/features/dispersion.yaml",
    "scenes/features/depth-of-field.yaml",
    "scenes/features/motion-blur.yaml",
    "scenes/features/refraction.yaml",
    "scenes/features/transparent-shadows.yaml",
    "scenes/features/textures.yaml",
    "scenes/features/csg.yaml",
    "scenes/features/meshes.yaml",
    "scenes/features/cornell-box.yaml",
    "scenes/features/colour-bleeding.yaml",
    "scenes/features/sky.yaml",
    "scenes/features/fog.yaml",
};

inline std::string scene_test_name(const ::testing::TestParamInfo<const char*>& param) {
    std::string name = param.param;
    name = name.substr(name.rfind('/') + 1);
    name = name.substr(0, name.find('.'));
    for (char& c : name)
        if (c == '-') c = '_';
    return name;
}

}  // namespace glint::testing
