#include "frame_sequence.h"

#include <charconv>
#include <filesystem>

#include "usage_error.h"

namespace glint::cli {

namespace {

std::optional<int> parse_frame(std::string_view text) {
    int value = 0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (error != std::errc() || end != text.data() + text.size() || text.empty() || value < 0)
        return std::nullopt;
    return value;
}

// Where the file name starts in `path`.
std::size_t name_start(const std::string& path) {
    const std::size_t slash = path.find_last_of('/');
    return slash == std::string::npos ? 0 : slash + 1;
}

}  // namespace

std::optional<FrameRange> parse_frame_range(std::string_view text) {
    const std::size_t dots = text.find("..");
    const auto first = parse_frame(text.substr(0, dots));
    const auto last = dots == std::string_view::npos ? first : parse_frame(text.substr(dots + 2));
    if (!first || !last || *last < *first) return std::nullopt;
    return FrameRange{*first, *last};
}

bool names_frames(const std::string& path) {
    return path.find('#', name_start(path)) != std::string::npos;
}

std::string frame_file(const std::string& pattern, int frame) {
    const std::size_t end = pattern.find_last_of('#') + 1;
    std::size_t start = end - 1;
    while (start > name_start(pattern) && pattern[start - 1] == '#') --start;
    std::string number = std::to_string(frame);
    if (number.size() < end - start) number.insert(0, end - start - number.size(), '0');
    return pattern.substr(0, start) + number + pattern.substr(end);
}

void check_frame(const Scene& scene, int frame, const std::string& option) {
    if (!scene.animation)
        throw UsageError{option + ": the scene is a still (it has no animation: {frames, fps})"};
    if (frame >= scene.animation->frames)
        throw UsageError{option + ": the scene's animation has frames 0.." +
                         std::to_string(scene.animation->frames - 1)};
}

std::optional<FrameRange> frames_to_render(const std::string& frames, const Scene& scene,
                                           const std::string& output) {
    const bool sequence = names_frames(output);
    if (!scene.animation) {
        if (!frames.empty()) check_frame(scene, 0, "--frames");
        if (sequence)
            throw UsageError{"the output \"" + output +
                             "\" names frames with '#', but the scene is a still (it has no "
                             "animation: {frames, fps})"};
        return std::nullopt;
    }
    if (frames.empty()) {
        if (!sequence) return std::nullopt;  // frame 0 as a still
        return FrameRange{0, scene.animation->frames - 1};
    }
    const auto range = parse_frame_range(frames);
    if (!range)
        throw UsageError{"--frames: expected A..B (frames A to B, A <= B) or A, got \"" + frames +
                         "\""};
    check_frame(scene, range->last, "--frames " + frames);
    if (!sequence)
        throw UsageError{"--frames: the output \"" + output +
                         "\" must name where each frame's number goes with '#' (e.g. " +
                         std::filesystem::path(output).stem().string() + ".####" +
                         std::filesystem::path(output).extension().string() + ")"};
    return range;
}

}  // namespace glint::cli
