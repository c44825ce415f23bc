// POV-Ray's radiosity rendered by glint's path tracer, in worked numbers: a white plane of
// diffuse 0.5 under a sky of radiance 1 everywhere reflects 0.5 (its irradiance pi, times
// 0.5 / pi), as POV-Ray 3.7's render of the same file shows (sRGB 188 of 255); POV-Ray 3.6
// adds the ambient 0.1 on top (sRGB 203: 0.6).
#include <gtest/gtest.h>

#include "glint/render/render.h"
#include "glint/scene/pov/pov_scene.h"

namespace glint {
namespace {

// The mean of the image's lower half (the plane) and of its top row (the sky).
struct Means {
    double plane = 0, sky = 0;
};

Means render_furnace(const std::string& version) {
    const std::string text = "#version " + version +
                             "; global_settings { assumed_gamma 1 radiosity { count 400 } }\n"
                             "background { rgb 1 }\n"
                             "camera { location <0, 1, -3> look_at <0, 0, 0> }\n"
                             "plane { y, 0 pigment { rgb 1 } finish { diffuse 0.5 } }\n";
    Scene scene = parse_pov_scene(text, "furnace.pov", make_read_sandbox("furnace.pov"));
    scene.settings.width = 32;
    scene.settings.height = 24;
    const Image image = render(World(scene), {}).image;
    Means m;
    for (int y = 12; y < 24; ++y)
        for (int x = 0; x < 32; ++x) m.plane += image.at(x, y).r / (12.0 * 32);
    for (int x = 0; x < 32; ++x) m.sky += image.at(x, 0).r / 32;
    return m;
}

TEST(PovRadiosityRender, APlaneUnderAWhiteSkyReflectsItsDiffuse) {
    const Means m = render_furnace("3.7");
    EXPECT_NEAR(m.plane, 0.5, 0.01);
    EXPECT_NEAR(m.sky, 1, 1e-6);
}

TEST(PovRadiosityRender, OlderScenesAddTheirAmbientGlow) {
    const Means m = render_furnace("3.6");
    EXPECT_NEAR(m.plane, 0.6, 0.012);
}

}  // namespace
}  // namespace glint
