// Counting a scene's contents for summarize_scene().
#include "glint/scene/scene_summary.h"

namespace glint {

namespace {

struct TriangleCount {
    std::size_t operator()(const Triangle&) const { return 1; }
    std::size_t operator()(const TriangleMesh& m) const { return m.data->triangles.size(); }
    std::size_t operator()(const Transformed& t) const { return triangle_count(*t.shape); }
    std::size_t operator()(const Moving& m) const { return triangle_count(*m.shape); }
    std::size_t operator()(const Csg& c) const {
        return triangle_count(*c.a) + triangle_count(*c.b);
    }
    std::size_t operator()(const auto&) const { return 0; }
};

struct LightCount {
    SceneSummary& s;
    void operator()(const PointLight&) const { ++s.point_lights; }
    void operator()(const SpotLight&) const { ++s.spot_lights; }
    void operator()(const DirectionalLight&) const { ++s.directional_lights; }
    void operator()(const AreaLight&) const { ++s.area_lights; }
};

}  // namespace

std::size_t triangle_count(const Shape& shape) { return std::visit(TriangleCount{}, shape); }

SceneSummary summarize_scene(const Scene& scene) {
    SceneSummary s;
    s.objects = scene.objects.size();
    s.materials = scene.materials.size();
    s.animation = scene.animation;
    s.moving_lights = scene.moving_lights.size();
    if (scene.sky) {
        s.sky_width = scene.sky->image->width;
        s.sky_height = scene.sky->image->height;
    }
    for (const SceneObject& object : scene.objects) {
        ++s.objects_by_shape[std::string(shape_name(object.shape))];
        s.triangles += triangle_count(object.shape);
        if (object.emits_light && emits(scene.materials[object.material])) ++s.emitting_objects;
        const Bounds3 b = bounds(object.shape);
        if (b.is_finite())
            s.bounds = merge(s.bounds, b);
        else
            ++s.unbounded_objects;
    }
    for (const Light& light : scene.lights) std::visit(LightCount{s}, light);
    return s;
}

}  // namespace glint
