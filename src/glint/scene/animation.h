// Animations: frame f of a scene shows it at the moment f / fps (Scene::animation). Shapes and
// the camera move by their keyframes at each ray's time, so a frame is the scene with the
// camera's shutter moved to its moment; lights move from frame to frame, placed at the shutter's
// opening.
#pragma once

#include "glint/math/transform.h"
#include "glint/scene/scene.h"

namespace glint {

// The moment frame `frame` starts: frame / fps.
float frame_time(const Animation& animation, int frame);

// The scene of frame `frame` (in [0, frames); a still's frame is 0): the shutter opens and closes
// frame_time later than the camera says, and the moving lights are placed at its opening.
Scene scene_at_frame(const Scene& scene, int frame);

// Puts each of the scene's moving lights where its keyframes have it at `time`.
void place_lights(Scene& scene, float time);

// Whether `t` turns, moves, mirrors and scales evenly only, so that a light's sphere, disk or
// rectangle keeps its shape.
bool keeps_shapes(const Transform& t);

// The light moved by `t` (which keeps_shapes): its position, direction and shape.
Light moved_light(const Light& light, const Transform& t);

}  // namespace glint
