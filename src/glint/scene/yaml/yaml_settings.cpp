// Reading the image settings and the camera, with the limits that keep a scene from asking for
// more memory or recursion than is sane, and the checks that keep the view well defined.
#include "glint/scene/yaml/yaml_settings.h"

#include <cmath>
#include <string>
#include <vector>

#include "glint/math/constants.h"
#include "glint/scene/settings_problem.h"

namespace glint {

namespace {
constexpr std::string_view kCameraTypes[] = {"cylindrical",     "fisheye",     "orthographic",
                                             "panoramic",       "perspective", "spherical",
                                             "ultra_wide_angle"};
constexpr std::string_view kCylinderAxes[] = {"horizontal", "vertical"};

// `filter: gaussian`, or a map with the type and its parameters.
FilterSpec read_filter(const YamlSource& source, const YAML::Node& node, const Field& field) {
    FilterSpec spec;
    if (!node.IsMap() && !node.IsScalar())
        throw type_error(source, node, field, "a filter name or map");
    if (!node.IsMap()) {
        const std::string name = read_string(source, node, field);
        const auto kind = filter_from_name(name);
        if (!kind) throw unknown_name(source, node, "filter", "filters", name, filter_names());
        spec.kind = *kind;
        spec.radius = default_filter_radius(spec.kind);
        return spec;
    }
    auto entries = read_map(source, node, field);
    const std::string type = read_type(source, node, entries, "filter", filter_names());
    spec.kind = *filter_from_name(type);
    std::vector<std::string_view> keys = {"type", "radius"};
    if (spec.kind == FilterKind::gaussian) keys.push_back("sigma");
    if (spec.kind == FilterKind::mitchell) keys.insert(keys.end(), {"b", "c"});
    const MapReader map(source, node, std::move(entries), type + " filter", keys);
    spec.radius = map.number("radius", {kMinFilterRadius, kMaxFilterRadius},
                             default_filter_radius(spec.kind));
    spec.sigma = map.number("sigma", kPositive, spec.sigma);
    spec.b = map.number("b", kAnyNumber, spec.b);
    spec.c = map.number("c", kAnyNumber, spec.c);
    if (const std::string problem = describe_problem(spec); !problem.empty()) {
        const MapEntry* at = map.find(spec.kind == FilterKind::gaussian ? "sigma" : "b");
        throw source.error_at(at ? at->value : node, problem);
    }
    return spec;
}

// `adaptive`: the threshold and the fewest samples a pixel takes; `samples` is the most.
AdaptiveSampling read_adaptive(const YamlSource& source, const YAML::Node& node, const Field& field,
                               const RenderSettings& s) {
    const MapReader map(source, node, field, "adaptive", {"threshold", "min_samples"});
    AdaptiveSampling a;
    a.threshold = map.number("threshold", kPositive, a.threshold);
    a.min_samples = map.integer("min_samples", {2, kMaxSamplesPerPixel},
                                std::min(a.min_samples, s.samples_per_pixel));
    return a;  // checked with the other settings (settings_problem)
}

// `photons`: the photon integrator's photons a pass and gathering radius.
PhotonSettings read_photons(const YamlSource& source, const YAML::Node& node, const Field& field) {
    const MapReader map(source, node, field, "photons", {"per_pass", "radius", "alpha"});
    PhotonSettings p;
    p.per_pass = map.integer("per_pass", {1, kMaxPhotonsPerPass}, p.per_pass);
    p.radius = map.number("radius", kNonNegative, p.radius);
    p.alpha = map.number("alpha", {0, 1, true, true}, p.alpha);
    return p;
}

// `shadow_map`: the resolution, bias and filter of the shadow maps of `shadows: map`.
ShadowMapSettings read_shadow_map(const YamlSource& source, const YAML::Node& node,
                                  const Field& field) {
    const MapReader map(source, node, field, "shadow_map", {"resolution", "bias", "filter"});
    ShadowMapSettings m;
    m.resolution = map.integer("resolution", {16, kMaxShadowMapResolution}, m.resolution);
    m.bias = map.number("bias", {0, 64}, m.bias);
    m.filter = map.integer("filter", {1, 15}, m.filter);
    if (m.filter % 2 == 0)
        throw source.error_at(map.require("filter").value,
                              "shadow_map filter must be odd (a texel and as many on each side), "
                              "got " +
                                  std::to_string(m.filter));
    return m;
}

// The node a problem of the settings as a whole is about: its key where the file has it, else
// the map it belongs in.
YAML::Node blamed_node(const MapReader& image, const YAML::Node& image_node, std::string_view key) {
    if (key.starts_with("adaptive.")) {
        const YAML::Node adaptive = image.require("adaptive").value;
        const std::string_view inner = key.substr(std::string_view("adaptive.").size());
        // read_adaptive has checked it: a map with distinct scalar keys.
        for (auto entry = adaptive.begin(); entry != adaptive.end(); ++entry)
            if (entry->first.Scalar() == inner) return entry->second;
        return adaptive;
    }
    if (const MapEntry* entry = image.find(key)) return entry->value;
    // An unset sampler is the integrator's, or adaptive sampling's, default.
    if (key == "sampler" && image.find("adaptive")) return image.require("adaptive").value;
    return image_node;
}

// The whole number at `key`, up to `ceiling`, refused above `limit` with the way to raise it. The
// limit bounds what the file asks: the fallback is not checked against it.
int limited_integer(const YamlSource& source, const MapReader& map, std::string_view key,
                    int ceiling, int limit, const char* flag, int fallback) {
    const int value = map.integer(key, {1, ceiling}, fallback);
    if (map.has(key) && value > limit) {
        throw source.error_at(map.require(key).value,
                              std::string(key) + " " + std::to_string(value) +
                                  " is more than the limit of " + std::to_string(limit),
                              {"raise the limit with " + std::string(flag) + " N"});
    }
    return value;
}

}  // namespace

RenderSettings read_image(const YamlSource& source, const YAML::Node& node, const Field& field,
                          const SceneLimits& limits) {
    const MapReader map(
        source, node, field, "image",
        {"width", "height", "integrator", "samples", "sampler", "filter", "adaptive", "photons",
         "next_event", "shadow_rays", "max_depth", "min_weight", "background",
         "transparent_shadows", "shadows", "shadow_map"});
    RenderSettings s;
    s.width = map.integer("width", {1, kMaxImageSide}, s.width);
    s.height = map.integer("height", {1, kMaxImageSide}, s.height);
    if (std::int64_t(s.width) * s.height > limits.image_pixels) {
        throw source.error_at(node,
                              "image is too large: " + std::to_string(s.width) + " x " +
                                  std::to_string(s.height) + " pixels, more than the " +
                                  "limit of " + std::to_string(limits.image_pixels),
                              {"raise the limit with --max-pixels N"});
    }
    const std::string integrator =
        map.choice("integrator", integrator_names(), "integrator", "integrators", "whitted");
    s.integrator = *integrator_from_name(integrator);
    if (map.has("sampler"))
        s.sampler =
            sampler_from_name(map.choice("sampler", sampler_names(), "sampler", "samplers", ""));
    if (const MapEntry* filter = map.find("filter"))
        s.filter = read_filter(source, filter->value, map.field("filter"));
    s.samples_per_pixel =
        limited_integer(source, map, "samples", kMaxSamplesPerPixel, limits.samples_per_pixel,
                        "--max-samples", s.samples_per_pixel);
    if (const MapEntry* adaptive = map.find("adaptive"))
        s.adaptive = read_adaptive(source, adaptive->value, map.field("adaptive"), s);
    if (const MapEntry* photons = map.find("photons"))
        s.photons = read_photons(source, photons->value, map.field("photons"));
    static constexpr std::string_view kNextEvent[] = {"all", "one"};
    if (map.choice("next_event", kNextEvent, "next-event strategy", "next-event strategies",
                   "one") == "all")
        s.next_event = NextEventStrategy::all;
    s.shadow_rays = map.integer("shadow_rays", {1, kMaxShadowRays}, s.shadow_rays);
    s.max_depth = limited_integer(source, map, "max_depth", kMaxDepth, limits.max_depth,
                                  "--max-ray-depth", s.max_depth);
    s.min_weight = map.number("min_weight", kUnitInterval, s.min_weight);
    s.background = map.color("background", s.background);
    s.transparent_shadows = map.boolean("transparent_shadows", s.transparent_shadows);
    if (map.choice("shadows", kShadowMethodNames, "shadow method", "shadow methods", "feelers") ==
        "map")
        s.shadows = ShadowMethod::map;
    if (const MapEntry* shadow_map = map.find("shadow_map"))
        s.shadow_map = read_shadow_map(source, shadow_map->value, map.field("shadow_map"));
    if (const std::optional<SettingsProblem> problem = settings_problem(s))
        throw source.error_at(blamed_node(map, node, problem->key), problem->message,
                              problem->notes);
    return s;
}

namespace {

// The height of a full-frame (36 x 24 mm) sensor in metres: what f_number's focal length is for.
constexpr float kSensorHeight = 0.024f;
constexpr int kMaxApertureBlades = 64;

// The thin lens: an aperture radius, or an f-number for scenes in metres; the focus distance
// and the aperture's shape, which a pinhole has none of.
void read_lens(const MapReader& map, CameraSpec& camera, std::vector<std::string>& warnings) {
    const YamlSource& source = map.source();
    if (map.has("aperture") && map.has("f_number")) {
        throw source.error_at(map.require("f_number").key_node,
                              "camera takes \"aperture\" or \"f_number\", not both",
                              {"aperture is the lens radius in scene units; f_number sets it "
                               "from the focal length of a 24 mm high sensor, in metres"});
    }
    if (map.has("aperture")) camera.lens.radius = map.number("aperture", kNonNegative);
    if (map.has("f_number")) {
        if (camera.projection != Projection::perspective) {
            throw source.error_at(
                map.require("f_number").key_node,
                camera_named(camera.projection) + " has no focal length for f_number",
                {"give its aperture radius with \"aperture\""});
        }
        const float n = map.number("f_number", kPositive);
        const float focal_length = kSensorHeight / 2 / std::tan(radians(camera.fov) / 2);
        camera.lens.radius = focal_length / (2 * n);
    }
    camera.lens.focus_distance =
        map.number("focus_distance", kPositive, distance(camera.from, camera.at));
    if (const MapEntry* blades = map.find("aperture_blades")) {
        const float n = map.number("aperture_blades", {0, float(kMaxApertureBlades)});
        if (n != std::floor(n) || n == 1 || n == 2) {
            throw source.error_at(blades->value,
                                  "camera aperture_blades must be 0 (round) or a whole number "
                                  "from 3 to " +
                                      std::to_string(kMaxApertureBlades) + ", got " +
                                      format_number(n));
        }
        camera.lens.blades = int(n);
    }
    camera.lens.blade_rotation = map.number("aperture_rotation", kAnyNumber, 0.0f);
    if (camera.lens.radius > 0) return;
    for (const std::string_view key : {"focus_distance", "aperture_blades", "aperture_rotation"})
        if (const MapEntry* entry = map.find(key))
            warnings.push_back(source.warning_at(
                entry->key_node, "camera " + std::string(key) +
                                     " does nothing without an aperture: a pinhole camera has no "
                                     "lens (give aperture or f_number for depth of field)"));
}

// The projection's own parameters: perspective's vertical fov, the wide projections' angles
// (up to a full turn), the view's height or a cylinder's extent along its axis.
void read_projection(const MapReader& map, CameraSpec& camera) {
    constexpr Range kTurn{0, 360, true, false};
    switch (camera.projection) {
        case Projection::perspective:
            camera.fov = map.number("fov", {0, 180, true, true}, camera.fov);
            break;
        case Projection::orthographic:
            camera.height = map.number("height", kPositive, camera.height);
            break;
        case Projection::fisheye:
        case Projection::ultra_wide_angle:
            camera.fov = map.number("fov", kTurn, 180);
            break;
        case Projection::panoramic:
            break;
        case Projection::cylindrical:
            camera.fov = map.number("fov", kTurn, 180);
            camera.height = map.number("height", kPositive, 1);
            camera.cylinder_axis_across = map.choice("axis", kCylinderAxes, "cylinder axis",
                                                     "cylinder axes", "vertical") == "horizontal";
            camera.cylinder_parallel = map.boolean("parallel", false);
            break;
        case Projection::spherical:
            camera.fov = map.number("fov", kTurn, 360);
            camera.vertical_fov = map.number("vertical_fov", {0, 180, true, false}, 180);
            break;
    }
}

// The shutter interval and the camera's keyframes, each a map of time, from, at and up.
void read_shutter(const MapReader& map, CameraSpec& camera) {
    const YamlSource& source = map.source();
    if (const MapEntry* shutter = map.find("shutter")) {
        const auto times =
            read_sequence(source, shutter->value, map.field("shutter"), "[open, close]", 2);
        camera.shutter_open = read_number(source, times[0], map.field("shutter"));
        camera.shutter_close = read_number(source, times[1], map.field("shutter"));
        if (!(camera.shutter_close >= camera.shutter_open)) {
            throw source.error_at(shutter->value, "camera shutter closes before it opens: [" +
                                                      format_number(camera.shutter_open) + ", " +
                                                      format_number(camera.shutter_close) + "]");
        }
    }
    const MapEntry* motion = map.find("motion");
    if (!motion) return;
    const auto frames =
        read_sequence(source, motion->value, map.field("motion"), "a list of keyframes");
    if (frames.size() < 2) {
        throw source.error_at(
            motion->value,
            "camera motion needs at least 2 keyframes, got " + std::to_string(frames.size()),
            {"a keyframe is {time: t, from: [x, y, z], at: [x, y, z], up: "
             "[x, y, z]}; from, at and up default to the camera's"});
    }
    for (std::size_t i = 0; i < frames.size(); ++i) {
        const Field field{"camera motion", "[" + std::to_string(i) + "]"};
        const MapReader frame(source, frames[i], field, "camera keyframe",
                              {"time", "from", "at", "up"});
        CameraKeyframe k{frame.number("time", kAnyNumber), frame.point("from", camera.from),
                         frame.point("at", camera.at), frame.direction("up", camera.up)};
        if (!camera.motion.empty() && !(k.time > camera.motion.back().time)) {
            throw source.error_at(frame.require("time").value,
                                  "keyframe times must increase, got " + format_number(k.time) +
                                      " after " + format_number(camera.motion.back().time));
        }
        const auto view = unit_vector(k.at - k.from);
        if (!view || length(cross(*view, k.up)) < 1e-6f) {
            throw source.error_at(frames[i],
                                  "camera keyframe needs from and at apart and up not along the "
                                  "line of sight");
        }
        camera.motion.push_back(k);
    }
}

}  // namespace

Animation read_animation(const YamlSource& source, const YAML::Node& node, const Field& field) {
    const MapReader map(source, node, field, "animation", {"frames", "fps"});
    Animation a;
    a.frames = map.integer("frames", {1, kMaxFrames});
    a.fps = map.number("fps", kPositive, a.fps);
    return a;
}

CameraSpec read_camera(const YamlSource& source, const YAML::Node& node, const Field& field,
                       std::vector<std::string>& warnings) {
    auto entries = read_map(source, node, field);
    const std::string type =
        read_type(source, node, entries, "camera", kCameraTypes, "perspective");
    // Each projection takes only its own parameters, so a fov on an orthographic camera is
    // reported rather than silently ignored.
    std::vector<std::string_view> keys{"type", "from", "at", "up", "aperture", "f_number"};
    keys.insert(keys.end(),
                {"focus_distance", "aperture_blades", "aperture_rotation", "shutter", "motion"});
    CameraSpec camera;
    for (const Projection p : kProjections)
        if (type == projection_name(p)) camera.projection = p;
    switch (camera.projection) {
        case Projection::perspective:
        case Projection::fisheye:
        case Projection::ultra_wide_angle:
            keys.push_back("fov");
            break;
        case Projection::orthographic:
            keys.push_back("height");
            break;
        case Projection::panoramic:
            break;
        case Projection::cylindrical:
            keys.insert(keys.end(), {"fov", "height", "axis", "parallel"});
            break;
        case Projection::spherical:
            keys.insert(keys.end(), {"fov", "vertical_fov"});
            break;
    }
    const MapReader map(source, node, std::move(entries), type + " camera", keys, TypeKey::listed);
    camera.from = map.point("from");
    camera.at = map.point("at");
    const auto view = unit_vector(camera.at - camera.from);
    if (!view) {
        throw source.error_at(map.require("at").value, "camera from and at must differ, both are " +
                                                           format_vector(to_vector(camera.at)));
    }
    camera.up = map.direction("up", camera.up);
    // Parallel vectors leave the image's horizontal axis, cross(view, up), undefined.
    if (length(cross(*view, camera.up)) < 1e-6f) {
        const MapEntry* up = map.find("up");
        throw source.error_at(up ? up->value : node,
                              "camera up is parallel to the view direction (at - from)",
                              {"the image's vertical follows up; give one that is not along the "
                               "line of sight"});
    }
    read_projection(map, camera);
    read_lens(map, camera, warnings);
    read_shutter(map, camera);
    return camera;
}

}  // namespace glint
