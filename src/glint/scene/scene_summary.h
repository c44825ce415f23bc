// What a scene holds, counted: objects by shape, triangles, materials, lights by kind and the
// world box of what is bounded (`glint info`).
#pragma once

#include <cstddef>
#include <map>
#include <optional>
#include <string>

#include "glint/math/bounds.h"
#include "glint/scene/scene.h"

namespace glint {

struct SceneSummary {
    std::size_t objects = 0;
    std::map<std::string, std::size_t> objects_by_shape;  // shape_name() -> count, sorted
    // Of meshes and lone triangles, through transforms, instances and CSG: an instance's mesh
    // counts once for every placement.
    std::size_t triangles = 0;
    std::size_t materials = 0;
    std::size_t point_lights = 0, spot_lights = 0, directional_lights = 0, area_lights = 0;
    // Objects whose material emits and that light the scene (SceneObject::emits_light); an area
    // light's visible face is its light's, not one of these.
    std::size_t emitting_objects = 0;
    int sky_width = 0, sky_height = 0;   // the sky image's size; 0 for a background colour
    Bounds3 bounds;                      // of the bounded objects; empty when there are none
    std::size_t unbounded_objects = 0;   // planes, and shapes built on them
    std::optional<Animation> animation;  // none: a still
    std::size_t moving_lights = 0;       // lights that move from frame to frame
};

SceneSummary summarize_scene(const Scene& scene);

// The triangles a shape holds (see SceneSummary::triangles).
std::size_t triangle_count(const Shape& shape);

}  // namespace glint
