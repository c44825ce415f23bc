// The frames `glint render` renders of an animated scene (Scene::animation), and the file each
// goes to: out.####.png names frame 7 out.0007.png.
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "glint/scene/scene.h"

namespace glint::cli {

struct FrameRange {
    int first = 0, last = 0;  // counted from 0, both rendered
};

// "A..B" (A <= B) or "A"; none for anything else.
std::optional<FrameRange> parse_frame_range(std::string_view text);

// Whether the file name of `path` holds a '#', where the frame number goes.
bool names_frames(const std::string& path);

// `pattern` with the last run of '#' in its file name replaced by the frame number, padded with
// zeros to the run's length: out.####.png, 7 -> out.0007.png; 12345 -> out.12345.png.
std::string frame_file(const std::string& pattern, int frame);

// Throws UsageError, naming `option`, unless the scene is an animation with frame `frame`.
void check_frame(const Scene& scene, int frame, const std::string& option);

// The frames a render of `scene` to `output` is: those --frames names (`frames`, may be empty),
// or every frame when the output names frames; none for a still. Throws UsageError for frames
// the scene does not have, or a sequence without '#' in the output's name (or the reverse).
std::optional<FrameRange> frames_to_render(const std::string& frames, const Scene& scene,
                                           const std::string& output);

}  // namespace glint::cli
