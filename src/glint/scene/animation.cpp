#include "glint/scene/animation.h"

#include <cmath>
#include <utility>
#include <variant>
#include <vector>

namespace glint {

namespace {

// How much longer `t` makes every length (keeps_shapes holds).
float scale_of(const Transform& t) { return length(t(Vector3{1, 0, 0})); }

Vector3 moved_direction(const Transform& t, Vector3 d) { return normalize(t(d)); }

AreaLight moved_area(const AreaLight& light, const Transform& t) {
    AreaLight moved = light;
    moved.center = t(light.center);
    const float s = scale_of(t);
    if (const auto* sphere = std::get_if<Sphere>(&light.shape)) {
        moved.shape = Sphere{t(sphere->center), sphere->radius * s};
    } else if (const auto* disk = std::get_if<Disk>(&light.shape)) {
        moved.shape = Disk{t(disk->center), Normal3(moved_direction(t, to_vector(disk->normal))),
                           disk->radius * s, disk->inner_radius * s};
    } else {
        std::vector<Point3> vertices = std::get<Polygon>(light.shape).vertices;
        for (Point3& v : vertices) v = t(v);
        // A similarity keeps the rectangle a rectangle, so it stays a polygon.
        moved.shape = std::get<Polygon>(make_polygon(std::move(vertices)));
    }
    return moved;
}

}  // namespace

float frame_time(const Animation& animation, int frame) { return float(frame) / animation.fps; }

Scene scene_at_frame(const Scene& scene, int frame) {
    Scene at = scene;
    if (!scene.animation || frame == 0) return at;
    const float t = frame_time(*scene.animation, frame);
    at.camera.shutter_open += t;
    at.camera.shutter_close += t;
    place_lights(at, at.camera.shutter_open);
    return at;
}

void place_lights(Scene& scene, float time) {
    for (const MovingLight& m : scene.moving_lights)
        scene.lights[m.index] = moved_light(m.at_rest, m.motion->at(time));
}

bool keeps_shapes(const Transform& t) {
    const Vector3 x = t(Vector3{1, 0, 0}), y = t(Vector3{0, 1, 0}), z = t(Vector3{0, 0, 1});
    const float xx = dot(x, x), yy = dot(y, y), zz = dot(z, z);
    constexpr float kTolerance = 1e-4f;
    const auto near = [&](float a, float b) { return std::abs(a - b) <= kTolerance * xx; };
    return xx > 0 && std::isfinite(xx) && near(yy, xx) && near(zz, xx) && near(dot(x, y), 0) &&
           near(dot(y, z), 0) && near(dot(x, z), 0);
}

Light moved_light(const Light& light, const Transform& t) {
    if (const auto* point = std::get_if<PointLight>(&light)) {
        PointLight moved = *point;
        moved.position = t(point->position);
        return moved;
    }
    if (const auto* spot = std::get_if<SpotLight>(&light)) {
        SpotLight moved = *spot;
        moved.position = t(spot->position);
        moved.direction = moved_direction(t, spot->direction);
        return moved;
    }
    if (const auto* sun = std::get_if<DirectionalLight>(&light)) {
        DirectionalLight moved = *sun;
        moved.direction = moved_direction(t, sun->direction);
        return moved;
    }
    return moved_area(std::get<AreaLight>(light), t);
}

}  // namespace glint
