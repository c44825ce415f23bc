// A linter for scenes: what loads and renders but is probably not what the author meant (no
// lights, a camera inside a sphere, a material that makes light). docs/cli.md explains each rule.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "glint/scene/scene.h"
#include "glint/scene/scene_error.h"

namespace glint {

struct LintWarning {
    std::string_view rule;  // the rule's name, as docs/cli.md lists it ("energy", ...)
    // What it is about: "camera", "object 3 (sphere)", "light 0 (point)", "material \"glass\"".
    // Objects and lights are numbered from 0 in the order the scene holds them (in a YAML
    // scene, the visible faces of area lights come before the `objects` list).
    std::string subject;
    std::string message;  // what is wrong and why it matters
    // Where the subject was read, when the loader kept it (SceneSources): the YAML loader does.
    std::optional<SourceLocation> location;
    // A note tells what the integrator makes of the scene; a warning, what is probably not meant.
    bool note = false;
};

// The rules' names, in the order lint_scene() applies them.
inline constexpr std::string_view kLintRules[] = {
    "no-lights", "camera-inside",   "light-inside", "energy",         "ambient",
    "ior",       "unused-material", "out-of-view",  "unused-setting", "cone-fallback"};

// Every warning, rule by rule in kLintRules' order, then in scene order.
std::vector<LintWarning> lint_scene(const Scene& scene);

// "object 3 (sphere)": how warnings and `glint info` name objects.
std::string object_subject(const Scene& scene, std::size_t index);

}  // namespace glint
