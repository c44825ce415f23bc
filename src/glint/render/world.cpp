// Building the render-time world from a Scene (primitives, acceleration structure, light
// buffers) and the shadow and spawn queries the integrator asks of it.
#include "glint/render/world.h"

#include <algorithm>
#include <cmath>
#include <span>
#include <utility>
#include <vector>

#include "glint/accel/mesh_bvh.h"
#include "glint/math/constants.h"
#include "glint/render/integrators/eye_media.h"

namespace glint {

namespace {

float max_abs_coordinate(Point3 p) {
    return std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z)});
}

// The magnitude of coordinates where hits commonly occur and eye rays start: the camera's
// position and the finite objects'. An object reaching out a thousand times as far
// as the median object (an unbounded quadric cut 10^5 out) is left out: its far hits get their
// own magnitude in ray_epsilon, and it would otherwise push every ray's origin off by as much.
float scene_scale(std::span<const Primitive> primitives, Point3 eye) {
    std::vector<float> scales;
    scales.reserve(primitives.size());
    for (const Primitive& primitive : primitives) {
        const Bounds3 b = bounds(primitive.shape);
        if (!b.is_empty() && b.is_finite())
            scales.push_back(std::max(max_abs_coordinate(b.min), max_abs_coordinate(b.max)));
    }
    float scale = max_abs_coordinate(eye);
    if (scales.empty()) return std::max(scale, 1e-6f);
    auto middle = scales.begin() + std::ptrdiff_t((scales.size() - 1) / 2);  // the lower median
    std::nth_element(scales.begin(), middle, scales.end());
    const float outlier = 1000 * std::max(*middle, scale);
    for (const float s : scales)
        if (s <= outlier) scale = std::max(scale, s);
    return std::max(scale, 1e-6f);
}

}  // namespace

World::World(Scene scene, AccelKind accel, ShadowAcceleration shadows)
    : settings_(scene.settings),
      camera_(scene.camera, scene.settings.width, scene.settings.height),
      ambient_(scene.ambient),
      sky_(scene.sky ? Sky(*scene.sky) : Sky(scene.settings.background)),
      fogs_(scene.fogs),
      atmosphere_(std::move(scene.atmosphere)),
      materials_(std::move(scene.materials)),
      lights_(std::move(scene.lights)) {
    primitives_.reserve(scene.objects.size());
    material_of_.reserve(scene.objects.size());
    for (SceneObject& object : scene.objects) {
        std::uint32_t visibility = kVisibleToCameraRays;
        if (object.casts_shadow) visibility |= kVisibleToShadowRays;
        add_object_light(object, std::uint32_t(primitives_.size()));
        operand_materials_ = operand_materials_ || has_operand_materials(object.shape);
        primitives_.push_back({std::move(object.shape), visibility});
        material_of_.push_back(object.material);
    }
    scene.objects = {};  // the moved-from shapes: freed before the structure is built
    // The two-level structure's lower level first, before anything traces the shapes: the own
    // BVH of each mesh traced whole (inside instances, transforms and CSG, and the small ones
    // that light buffers list), rather than triangle by triangle.
    const auto buffered = [&](const Light& light) {
        return shadows.light_buffer && std::holds_alternative<PointLight>(light);
    };
    const bool any_buffer = std::any_of(lights_.begin(), lights_.end(), buffered);
    bind_mesh_bvhs(primitives_, [&](const Shape& shape) {
        return any_buffer && LightBuffer::tests_whole(shape);
    });
    carries_pencils_ = settings_.integrator == IntegratorKind::cone ||
                       std::any_of(materials_.begin(), materials_.end(), [](const Material& m) {
                           const auto* image = std::get_if<ImageTexture>(&m.color);
                           return image && (image->filter == TextureFilter::trilinear ||
                                            image->filter == TextureFilter::ewa);
                       });
    if (!lights_scene_.empty()) {
        lights_scene_.resize(primitives_.size(), 0);
        object_light_of_.resize(primitives_.size(), -1);
    }
    EyeMedia eye = find_eye_media(camera_, settings_.width, settings_.height, primitives_,
                                  materials_, material_of_);
    for (const std::uint32_t p : eye.primitives) {
        const Material& m = materials_[material_of_[p]];
        eye_media_ = eye_media_.entered(p, &m, m.ior);
    }
    warnings_.insert(warnings_.end(), eye.warnings.begin(), eye.warnings.end());
    const IntegratorKind kind = settings_.integrator;
    if (!atmosphere_.empty() && kind != IntegratorKind::whitted &&
        kind != IntegratorKind::distributed)
        warnings_.push_back("the " + std::string(integrator_info(kind).name) +
                            " integrator draws no atmosphere: media outside objects are marched "
                            "by the whitted and distributed integrators");
    if (!fogs_.empty() && kind != IntegratorKind::whitted && kind != IntegratorKind::distributed)
        warnings_.push_back("the " + std::string(integrator_info(kind).name) +
                            " integrator draws no fog: fog is drawn by the whitted and "
                            "distributed integrators");
    aggregate_ = make_aggregate(accel, primitives_);
    scene_scale_ = scene_scale(primitives_, camera_.eye());
    const Bounds3 bounded = aggregate_->bounds();
    if (!bounded.is_empty() && bounded.is_finite()) {
        scene_radius_ = std::max(length(bounded.diagonal()) / 2, 1e-6f);
        scene_center_ = bounded.min + bounded.diagonal() / 2;
    }
    shadows_ = shadows;
    if (!atmosphere_.empty()) {
        // The finite objects' box: a ray that misses them all (or meets only a plane far
        // away) leaves the atmosphere where it leaves the box.
        atmosphere_box_ = Bounds3{camera_.eye(), camera_.eye()};
        for (const Primitive& p : primitives_)
            if (const Bounds3 b = glint::bounds(p.shape); !b.is_empty() && b.is_finite())
                atmosphere_box_ = merge(atmosphere_box_, b);
        for (const Light& light : lights_) {
            if (const auto* point = std::get_if<PointLight>(&light))
                atmosphere_box_ = merge(atmosphere_box_, point->position);
            else if (const auto* spot = std::get_if<SpotLight>(&light))
                atmosphere_box_ = merge(atmosphere_box_, spot->position);
            else if (const auto* area = std::get_if<AreaLight>(&light))
                atmosphere_box_ = merge(atmosphere_box_, area->center);
        }
    }
    for (const Light& light : lights_) {
        light_buffers_.push_back(
            buffered(light)
                ? std::make_unique<LightBuffer>(std::get<PointLight>(light).position, primitives_)
                : nullptr);
    }
    if (settings_.shadows == ShadowMethod::map) build_shadow_maps();
}

void World::build_shadow_maps() {
    const ShadowMapSettings& s = settings_.shadow_map;
    // Moving shapes cast their shadows where they are as the shutter opens.
    const float time = camera_.shutter_open();
    for (const Light& light : lights_) {
        std::optional<ShadowMap> map;
        if (const auto* point = std::get_if<PointLight>(&light))
            map = ShadowMap::cube(point->position, 0, *aggregate_, s, time);
        else if (const auto* spot = std::get_if<SpotLight>(&light))
            map = ShadowMap::cube(spot->position, 0, *aggregate_, s, time);
        else if (const auto* area = std::get_if<AreaLight>(&light))
            // Seen from its centre, as wide as the disk of its area.
            map = ShadowMap::cube(
                area->center,
                std::visit([](const auto& shape) { return std::sqrt(shape.area() / kPi); },
                           area->shape),
                *aggregate_, s, time);
        else if (const auto* sun = std::get_if<DirectionalLight>(&light);
                 sun && !aggregate_->bounds().is_empty())
            map = ShadowMap::parallel(sun->direction, aggregate_->bounds(), *aggregate_, s, time);
        shadow_maps_.push_back(std::move(map));
    }
}

void World::add_object_light(const SceneObject& object, std::uint32_t primitive) {
    const Material& material = materials_[object.material];
    if (!object.emits_light || !emits(material)) return;
    if (lights_scene_.empty()) {
        lights_scene_.assign(primitive, 0);
        object_light_of_.assign(primitive, -1);
    }
    // Primitives before this one that did not emit.
    lights_scene_.resize(primitive, 0);
    object_light_of_.resize(primitive, -1);
    lights_scene_.push_back(1);
    object_light_of_.push_back(-1);
    // Light in the surface's colour varies over it: the rays that find it carry it alone.
    if (is_black(material.emission)) return;
    if (auto surface = SurfaceSampler::of(object.shape)) {
        object_light_of_.back() = std::int32_t(object_lights_.size());
        object_lights_.push_back(
            {std::move(*surface), material.emission, material.emits_both_sides, primitive});
    } else if (!integrator_info(settings_.integrator).physically_based &&
               settings_.integrator != IntegratorKind::whitted) {
        warnings_.push_back("object " + std::to_string(primitive) + " (" +
                            std::string(shape_name(object.shape)) +
                            ") emits light but cannot light the scene: only spheres, disks, "
                            "triangles, convex polygons, boxes, cylinders and meshes can");
    }
}

bool World::occluded_towards(std::size_t light, const Ray& ray, Interval t_range,
                             std::uint32_t& last_occluder) const {
    if (!shadows_.occluder_cache) last_occluder = LightBuffer::kNoPrimitive;
    if (const LightBuffer* buffer = light_buffers_[light].get()) {
        if (const auto answer = buffer->occluded(ray, t_range, last_occluder)) return *answer;
    }
    // Directional lights, point lights without a buffer and crowded cells ask the aggregate,
    // which says whether, not what: there is nothing to cache.
    return aggregate_->occluded(ray, t_range, kVisibleToShadowRays);
}

float World::ray_epsilon(Point3 p) const {
    return kRelativeRayEpsilon * std::max(scene_scale_, max_abs_coordinate(p));
}

Ray World::spawn_ray(Point3 p, Normal3 n, Vector3 d, float error, float time) const {
    const float distance = std::max(ray_epsilon(p), 2 * error);
    const float offset = dot(n, d) >= 0 ? distance : -distance;
    return {p + to_vector(n) * offset, d, time};
}

float World::atmosphere_reach(const Ray& ray) const {
    const auto chord = intersect_slabs(atmosphere_box_, ray, {0, kInfinity});
    return chord ? chord->max : 0;
}

}  // namespace glint
