// Small scenes whose light the global-illumination integrators must agree on: a furnace with an
// exact answer, a floor lit straight from three kinds of light, and a red wall beside a white
// floor. Each takes the integrator to render it with.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "common/under_sanitizer.h"
#include "glint/image/image.h"
#include "glint/scene/scene.h"

namespace glint::testing {

// Inside a closed sphere whose walls reflect albedo rho diffusely and emit Le: every ray sees
// Le + rho Le + rho^2 Le + ... = Le / (1 - rho), the sum cut after max_depth bounces.
inline Scene furnace(float albedo, Color le, IntegratorKind integrator = IntegratorKind::path) {
    Scene scene;
    scene.settings.width = scene.settings.height = 8;
    scene.settings.integrator = integrator;
    scene.settings.samples_per_pixel = kUnderSanitizer ? 64 : 256;
    scene.settings.max_depth = 200;
    scene.camera.from = {0.2f, -0.1f, 0.3f};
    scene.camera.at = {1, 0, 0};
    scene.camera.fov = 90;
    Material wall;
    wall.ka = 0;
    wall.kd = albedo;
    wall.emission = le;
    scene.materials.push_back(wall);
    scene.objects.push_back({Sphere{{0, 0, 0}, 2}, 0});
    return scene;
}

// A floor lit by a point light falling off as 1 / d^2, a rectangle area light and an emitting
// disk, and nothing else: one bounce of the path tracer is the distributed integrator's direct
// lighting, Phong's diffuse term being Lambert's.
inline Scene directly_lit(IntegratorKind integrator) {
    Scene scene;
    scene.settings.width = 24;
    scene.settings.height = 16;
    scene.settings.integrator = integrator;
    scene.settings.samples_per_pixel = kUnderSanitizer ? 64 : 256;
    scene.settings.max_depth = 1;
    scene.settings.filter = FilterSpec{FilterKind::box, 0.5f};
    scene.camera.from = {0, 4, -6};
    scene.camera.at = {0, 0, 0};
    scene.camera.fov = 50;
    Material floor;
    floor.ka = 0;
    floor.kd = 0.7f;
    floor.color = Color{0.9f, 0.8f, 0.6f};
    Material lamp;
    lamp.ka = lamp.kd = 0;
    lamp.emission = Color::gray(3);
    scene.materials = {floor, lamp};
    scene.objects.push_back({Plane{{0, 0, 0}, {0, 1, 0}}, 0});
    scene.objects.push_back({Disk{{1.5f, 1.5f, 0}, {0, -1, 0}, 0.5f}, 1});
    PointLight point;
    point.position = {-2, 2, -1};
    point.color = Color::gray(2);
    point.attenuation = {0, 0, 1};
    AreaLight area = *rectangle_light({0, 3, 2}, {1, 0, 0}, {0, 0, 1});
    area.color = Color::gray(4);
    area.attenuation = {0, 0, 1};
    scene.lights = {point, area};
    return scene;
}

// Colour bleeding: a white floor beside a red wall, lit from above. The path tracer sees the
// floor near the wall turn red, light the wall reflects; the distributed integrator does not.
inline Scene red_wall(IntegratorKind integrator) {
    Scene scene;
    scene.settings.width = scene.settings.height = 8;
    scene.settings.integrator = integrator;
    scene.settings.samples_per_pixel = kUnderSanitizer ? 32 : 128;
    scene.camera.from = {-1.5f, 0.3f, 0};
    scene.camera.at = {0, 0, 0};
    scene.camera.fov = 20;
    Material white, red;
    white.ka = red.ka = 0;
    white.kd = red.kd = 0.8f;
    red.color = Color{0.9f, 0.1f, 0.1f};
    scene.materials = {white, red};
    scene.objects.push_back({Plane{{0, 0, 0}, {0, 1, 0}}, 0});
    scene.objects.push_back({Box{{0.1f, 0, -3}, {0.3f, 2, 3}}, 1});
    PointLight light;
    light.position = {-1, 3, 0};
    light.attenuation = {0, 0, 1};
    light.color = Color::gray(10);
    scene.lights.push_back(light);
    return scene;
}

// Every pixel of a furnace sees the same light: the image's mean must be the exact answer
// within 4 standard errors (the pixels' spread over the square root of their count) and 1%, and
// no pixel may lie 6 standard deviations off.
inline void expect_furnace_answer(const Image& image, Color expected) {
    const double n = double(image.pixels.size());
    for (int channel = 0; channel < 3; ++channel) {
        const auto of = [&](const Color& c) {
            return double(channel == 0 ? c.r : channel == 1 ? c.g : c.b);
        };
        double sum = 0, squares = 0;
        for (const Color& c : image.pixels) {
            sum += of(c);
            squares += of(c) * of(c);
        }
        const double mean = sum / n, sd = std::sqrt(std::max(0.0, squares / n - mean * mean));
        const double want = of(expected);
        EXPECT_NEAR(mean, want, std::max(0.01 * want, 4 * sd / std::sqrt(n))) << channel;
        for (const Color& c : image.pixels) EXPECT_NEAR(of(c), want, 6 * sd + 1e-6) << channel;
    }
}

}  // namespace glint::testing
