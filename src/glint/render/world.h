// The render-time form of a Scene: primitives with their acceleration structure, materials,
// lights and camera, plus the scene-scaled epsilon that keeps secondary rays off their surface.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "glint/accel/aggregate.h"
#include "glint/accel/light_buffer.h"
#include "glint/accel/make_aggregate.h"
#include "glint/camera/camera.h"
#include "glint/math/huge_page_allocator.h"
#include "glint/render/integrators/medium_stack.h"
#include "glint/render/shadow_map.h"
#include "glint/scene/scene.h"
#include "glint/shading/object_light.h"

namespace glint {

// How shadow feelers are sped up beyond the acceleration structure. Neither changes a result.
struct ShadowAcceleration {
    // A light buffer per point light (Haines and Greenberg 1986). Off by default: against the
    // wide BVH it no longer pays (bench/README.md, docs/acceleration.md).
    bool light_buffer = false;
    // With a light buffer: test first the primitive that last shadowed from that light
    // (Haines and Greenberg's shadow cache), per thread. Off by default: measured to cost more
    // than it saves once the acceleration structure answers crowded cells (bench/README.md).
    bool occluder_cache = false;
};

class World {
public:
    // The scene must be valid as the loaders guarantee (positive radii, known materials, ...).
    // Taken by value: a caller done with its scene moves it in, and the shapes are not copied.
    explicit World(Scene scene, AccelKind accel = AccelKind::bvh, ShadowAcceleration shadows = {});

    const RenderSettings& settings() const { return settings_; }
    const Camera& camera() const { return camera_; }
    Color ambient() const { return ambient_; }
    // What rays that leave the scene see: the scene's sky image, or its background colour.
    const Sky& sky() const { return sky_; }
    std::span<const Fog> fogs() const { return fogs_; }
    // The media outside objects, and how far along a ray they reach: to where it leaves the
    // box around the finite objects, the lights and the eye.
    const std::vector<Medium>& atmosphere() const { return atmosphere_; }
    float atmosphere_reach(const Ray& ray) const;
    // The scene's lights, in scene order (light buffers and shadow caches are indexed by it).
    std::span<const Light> lights() const { return lights_; }
    // The objects whose material emits light and whose surface can be drawn on, in scene order.
    std::span<const ObjectLight> object_lights() const { return object_lights_; }
    // Whether a primitive lights the scene (it emits and its object's emits_light is on), and
    // its index among object_lights(), -1 when it has none (it emits nothing, only glows, or
    // cannot be drawn on).
    bool lights_scene(std::uint32_t primitive) const {
        return !lights_scene_.empty() && lights_scene_[primitive];
    }
    std::int32_t object_light_index(std::uint32_t primitive) const {
        return object_light_of_.empty() ? -1 : object_light_of_[primitive];
    }
    // Whether eye rays carry their pencils (pencil.h): some material's image texture filters
    // over the footprint of a pixel (trilinear or ewa), or the integrator traces cones as wide
    // as the pixel.
    bool carries_pencils() const { return carries_pencils_; }
    // What the user should know about the world as built ("an emitting torus cannot light").
    const std::vector<std::string>& warnings() const { return warnings_; }
    // The refracting objects eye rays start in (eye_media.h), at their own indices: vacuum for
    // a camera outside them all.
    const MediumStack& eye_media() const { return eye_media_; }
    // What the acceleration structure is built over, in scene order (to build others beside it).
    std::span<const Primitive> primitives() const { return primitives_; }
    // The acceleration structure over primitives() (for its statistics).
    const Aggregate& aggregate() const { return *aggregate_; }

    std::optional<Hit> intersect(const Ray& ray, Interval t_range, std::uint32_t mask) const {
        return aggregate_->intersect(ray, t_range, mask);
    }
    // The nearest hit of what camera rays see, and the same for a packet of rays at once (a
    // tile's eye rays): hits[i] is nearest_hit(rays[i]), bit for bit.
    std::optional<Hit> nearest_hit(const Ray& ray) const {
        return aggregate_->intersect(ray, {0, kInfinity}, kVisibleToCameraRays);
    }
    void nearest_hits(std::span<const Ray> rays, std::optional<Hit>* hits) const {
        aggregate_->intersect_packet(rays, {0, kInfinity}, kVisibleToCameraRays, hits);
    }
    bool occluded(const Ray& ray, Interval t_range, std::uint32_t mask) const {
        return aggregate_->occluded(ray, t_range, mask);
    }
    // Whether a primitive that casts shadows blocks the feeler `ray` towards lights()[light]
    // within t_range. last_occluder is the caller's (per thread) memory of the primitive that
    // blocked this light last: with a light buffer and the occluder cache on, it is tested
    // first and updated.
    // With shadows: map, light's shadow map (none for lights that have none).
    const ShadowMap* shadow_map(std::size_t light) const {
        return light < shadow_maps_.size() && shadow_maps_[light] ? &*shadow_maps_[light] : nullptr;
    }
    bool occluded_towards(std::size_t light, const Ray& ray, Interval t_range,
                          std::uint32_t& last_occluder) const;

    SurfacePoint surface_at(const Ray& ray, const Hit& hit, Uv uv = Uv::compute) const {
        return glint::surface_at(primitives_[hit.primitive].shape, ray, hit.shape_hit, uv);
    }
    const Material& material_of(std::uint32_t primitive) const {
        return materials_[material_of_[primitive]];
    }
    // Its index among the scene's materials.
    std::uint32_t material_index_of(std::uint32_t primitive) const {
        return material_of_[primitive];
    }
    // The material where the hit lies: its primitive's, or the CSG operand's it lies on, when
    // that operand has its own (csg.h); and its index.
    const Material& material_at(const Hit& hit) const { return materials_[material_index_at(hit)]; }
    std::uint32_t material_index_at(const Hit& hit) const {
        if (operand_materials_) [[unlikely]]
            if (const std::uint32_t own =
                    operand_material(primitives_[hit.primitive].shape, hit.shape_hit))
                return own - 1;
        return material_of_[hit.primitive];
    }

    // The radius of a sphere around the bounded geometry (1 when there is none): the scale of
    // the scene, for weighing lights whose intensity does not fall off with distance.
    float scene_radius() const { return scene_radius_; }
    Point3 scene_center() const { return scene_center_; }

    // How far a secondary ray's origin is moved off the surface at p: a fixed fraction of the
    // larger of the scene's extent and p's own magnitude, since float rounding error grows with
    // the magnitude of the coordinates involved.
    float ray_epsilon(Point3 p) const;
    // A ray leaving the surface point p in the unit direction d, its origin moved off the
    // surface to the side d goes (given by the geometric normal n): by ray_epsilon(p), or by
    // twice the point's own error when that is larger; traced at `time`.
    Ray spawn_ray(Point3 p, Normal3 n, Vector3 d, float error = 0, float time = 0) const;

private:
    void add_object_light(const SceneObject& object, std::uint32_t primitive);
    void build_shadow_maps();

    RenderSettings settings_;
    Camera camera_;
    Color ambient_;
    Sky sky_;
    std::vector<Fog> fogs_;
    std::vector<Medium> atmosphere_;
    Bounds3 atmosphere_box_;
    std::vector<Material> materials_;
    std::vector<Light> lights_;
    std::vector<ObjectLight> object_lights_;
    std::vector<std::string> warnings_;
    MediumStack eye_media_;  // holds pointers into materials_, which never reallocates
    LargeVector<Primitive> primitives_;
    std::vector<std::uint32_t> material_of_;  // per primitive
    bool operand_materials_ = false;          // some CSG paints an operand with its own
    std::unique_ptr<Aggregate> aggregate_;    // over primitives_
    ShadowAcceleration shadows_;
    std::vector<std::unique_ptr<LightBuffer>> light_buffers_;  // per light; null for none
    std::vector<std::optional<ShadowMap>> shadow_maps_;        // per light, with shadows: map
    bool carries_pencils_ = false;
    float scene_scale_ = 1;  // largest coordinate magnitude of bounded geometry
    float scene_radius_ = 1;
    Point3 scene_center_;
    // Per primitive, filled only when some object emits light.
    std::vector<std::uint8_t> lights_scene_;
    std::vector<std::int32_t> object_light_of_;
};

// Relative size of the secondary-ray offset: about 80 float ulps of the coordinates involved.
inline constexpr float kRelativeRayEpsilon = 1e-5f;

}  // namespace glint
