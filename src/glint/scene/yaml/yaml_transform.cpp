// Reading transforms: each step is a one-key map; the steps compose so that the first written
// is the first applied to the object.
#include "glint/scene/yaml/yaml_transform.h"

#include <cmath>

#include "glint/scene/yaml/yaml_map_reader.h"

namespace glint {

namespace {

constexpr std::string_view kSteps[] = {"matrix", "rotate", "scale", "translate"};

Transform read_rotation(const YamlSource& source, const YAML::Node& node, const Field& field) {
    if (node.IsSequence()) {
        const Vector3 euler = read_vector(source, node, field);
        return Transform::rotate({0, 0, 1}, euler.z) * Transform::rotate({0, 1, 0}, euler.y) *
               Transform::rotate({1, 0, 0}, euler.x);
    }
    const MapReader map(source, node, field, "rotate", {"axis", "angle"});
    return Transform::rotate(map.direction("axis"), map.number("angle", kAnyNumber));
}

Transform read_scale(const YamlSource& source, const YAML::Node& node, const Field& field) {
    const Vector3 s = node.IsSequence() ? read_vector(source, node, field)
                                        : Vector3{1, 1, 1} * read_number(source, node, field);
    if (s.x == 0 || s.y == 0 || s.z == 0) {
        throw source.error_at(node, "scale factors must be non-zero, got " + format_vector(s),
                              {"a zero scale flattens the object and cannot be inverted"});
    }
    return Transform::scale(s.x, s.y, s.z);
}

Transform read_matrix(const YamlSource& source, const YAML::Node& node, const Field& field) {
    const auto rows = read_sequence(source, node, field, "a 4x4 matrix (4 rows of 4 numbers)", 4);
    Matrix4 m;
    for (std::size_t i = 0; i < 4; ++i) {
        const Field row_field{field.what, field.key + "[" + std::to_string(i) + "]"};
        const auto row = read_sequence(source, rows[i], row_field, "a row of 4 numbers", 4);
        for (std::size_t j = 0; j < 4; ++j) m.m[i][j] = read_number(source, row[j], row_field);
    }
    if (m.m[3][0] != 0 || m.m[3][1] != 0 || m.m[3][2] != 0 || m.m[3][3] != 1) {
        throw source.error_at(rows[3], "the last row of a transform matrix must be [0, 0, 0, 1]",
                              {"only affine transforms are supported"});
    }
    const auto t = Transform::from_matrix(m);
    if (!t) throw source.error_at(node, "transform matrix is singular: it has no inverse");
    return *t;
}

}  // namespace

Transform read_transform(const YamlSource& source, const YAML::Node& node, const Field& field) {
    const auto steps = read_sequence(source, node, field, "a list of transform steps");
    Transform world_from_object;
    for (std::size_t i = 0; i < steps.size(); ++i) {
        const Field step_field{field.what, field.key + "[" + std::to_string(i) + "]"};
        const auto entries = read_map(source, steps[i], step_field);
        if (entries.size() != 1) {
            throw source.error_at(
                steps[i],
                "a transform step is a map with one key, got " + std::to_string(entries.size()),
                {"steps are: " + join(kSteps)});
        }
        const MapEntry& step = entries.front();
        const Field value_field{"transform", step.key, step.key_node};
        Transform t;
        if (step.key == "translate") {
            t = Transform::translate(read_vector(source, step.value, value_field));
        } else if (step.key == "rotate") {
            t = read_rotation(source, step.value, value_field);
        } else if (step.key == "scale") {
            t = read_scale(source, step.value, value_field);
        } else if (step.key == "matrix") {
            t = read_matrix(source, step.value, value_field);
        } else {
            throw unknown_name(source, step.key_node, "transform step", "steps", step.key, kSteps);
        }
        world_from_object = t * world_from_object;
    }
    return world_from_object;
}

std::shared_ptr<const AnimatedTransform> read_motion(const YamlSource& source,
                                                     const YAML::Node& node, const Field& field) {
    const auto frames = read_sequence(source, node, field, "a list of keyframes");
    if (frames.size() < 2) {
        throw source.error_at(
            node, "motion needs at least 2 keyframes, got " + std::to_string(frames.size()),
            {"a keyframe is {time: t, transform: [steps]}"});
    }
    std::vector<Keyframe> keyframes;
    for (std::size_t i = 0; i < frames.size(); ++i) {
        const Field frame_field{field.what, field.key + "[" + std::to_string(i) + "]"};
        const MapReader map(source, frames[i], frame_field, "keyframe", {"time", "transform"});
        Keyframe k{map.number("time", kAnyNumber), Transform{}};
        if (!keyframes.empty() && !(k.time > keyframes.back().time)) {
            throw source.error_at(map.require("time").value,
                                  "keyframe times must increase, got " + format_number(k.time) +
                                      " after " + format_number(keyframes.back().time));
        }
        if (const MapEntry* t = map.find("transform"))
            k.world_from_object = read_transform(source, t->value, map.field("transform"));
        keyframes.push_back(k);
    }
    if (const std::string problem = AnimatedTransform::describe_problem(keyframes);
        !problem.empty())
        throw source.error_at(node, "motion: " + problem);
    return std::make_shared<const AnimatedTransform>(std::move(keyframes));
}

}  // namespace glint
