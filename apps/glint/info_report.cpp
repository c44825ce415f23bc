// The text and JSON forms of `glint info`'s report. Both are built with snprintf, so that numbers
// print the same in both.
#include "info_report.h"

#include <cstdarg>
#include <cstdio>

#include "glint/render/json_string.h"
#include "glint/render/memory_estimate.h"
#include "glint/scene/integrators.h"

namespace glint::cli {

namespace {

// printf into a std::string, for short lines: text longer than 511 bytes (a path, a message) is
// appended directly.
[[gnu::format(printf, 2, 3)]] void append(std::string& out, const char* format, ...) {
    char line[512];
    va_list args;
    va_start(args, format);
    const int n = std::vsnprintf(line, sizeof line, format, args);
    va_end(args);
    if (n > 0) out.append(line, std::size_t(n) < sizeof line ? std::size_t(n) : sizeof line - 1);
}

std::string plural(std::size_t n, const char* one, const char* many) {
    return std::to_string(n) + " " + (n == 1 ? one : many);
}

std::string point_text(Point3 p) {
    char text[96];
    std::snprintf(text, sizeof text, "(%g, %g, %g)", p.x, p.y, p.z);
    return text;
}

std::string point_json(Point3 p) {
    char text[96];
    std::snprintf(text, sizeof text, "[%.7g, %.7g, %.7g]", p.x, p.y, p.z);
    return text;
}

std::string lights_text(const SceneSummary& s) {
    const std::size_t total = s.point_lights + s.spot_lights + s.directional_lights + s.area_lights;
    std::string out = std::to_string(total);
    const std::pair<std::size_t, const char*> kinds[] = {{s.point_lights, "point"},
                                                         {s.spot_lights, "spot"},
                                                         {s.directional_lights, "directional"},
                                                         {s.area_lights, "area"}};
    const char* separator = ": ";
    for (const auto& [n, name] : kinds) {
        if (n == 0) continue;
        out += separator + std::to_string(n) + " " + name;
        separator = ", ";
    }
    out += "; " + plural(s.emitting_objects, "emitting object", "emitting objects");
    return out;
}

// The text broken at spaces into lines of at most kTextWidth columns (a longer word stays whole),
// the lines after the first indented by four.
constexpr std::size_t kTextWidth = 100;

std::string wrapped(const std::string& text) {
    std::string out;
    std::size_t start = 0;
    const std::string indent = "    ";
    while (true) {
        const std::size_t room = kTextWidth - (start == 0 ? 0 : indent.size());
        if (text.size() - start <= room) {
            out += (start == 0 ? "" : indent) + text.substr(start) + "\n";
            return out;
        }
        std::size_t cut = text.rfind(' ', start + room);
        if (cut == std::string::npos || cut <= start) cut = text.find(' ', start + room);
        if (cut == std::string::npos) {
            out += (start == 0 ? "" : indent) + text.substr(start) + "\n";
            return out;
        }
        out += (start == 0 ? "" : indent) + text.substr(start, cut - start) + "\n";
        start = cut + 1;
    }
}

// "scene.yaml:14:3: " like a compiler's messages, when the warning has a place.
std::string where(const LintWarning& w) {
    if (!w.location) return "";
    return w.location->file + ":" + std::to_string(w.location->line) + ":" +
           std::to_string(w.location->column) + ": ";
}

void accel_text(std::string& out, std::string_view name, const AccelStats& a) {
    append(out, "\nAcceleration structure: %.*s\n", int(name.size()), name.data());
    if (!a.available) {
        append(out, "  (its nodes and leaves are not shown by its API)\n");
    } else {
        const bool grid = name == "grid";
        if (grid) {
            append(out, "  cells        %zu (%zu occupied, %zu empty)\n", a.leaves,
                   a.leaves - a.empty_leaves, a.empty_leaves);
        } else {
            append(out, "  nodes        %zu interior, %zu leaves (%zu empty)\n", a.interior_nodes,
                   a.leaves, a.empty_leaves);
            append(out, "  depth        max %d, mean leaf depth %.2f\n", a.max_depth,
                   a.mean_leaf_depth);
        }
        append(out, "  %-12s min %zu, mean %.2f, max %zu primitives\n",
               grid ? "per cell" : "leaf size", a.min_leaf_size, a.mean_leaf_size, a.max_leaf_size);
        append(out, "  references   %zu in %s\n", a.references, grid ? "cells" : "leaves");
        append(out, "  SAH cost     %.2f (node step %g, primitive test %g)\n", a.sah_cost,
               kSahTraversalCost, kSahIntersectionCost);
    }
    if (a.unbounded > 0)
        append(out, "  unbounded    %zu, tested by every ray beside the structure\n", a.unbounded);
    const std::string bytes = std::to_string(a.memory_bytes) + " bytes";
    const std::string memory = format_bytes(a.memory_bytes);
    append(out, "  memory       %s\n",
           (memory == bytes ? bytes : memory + " (" + bytes + ")").c_str());
}

}  // namespace

std::string info_text(const InfoReport& r) {
    const SceneSummary& s = r.summary;
    const RenderSettings& image = r.settings;
    const std::string_view integrator = integrator_name(image.integrator);
    std::string out;
    out += "Scene        " + r.scene + "\n";
    append(out, "Image        %dx%d, %d spp, %.*s integrator, max depth %d\n", image.width,
           image.height, image.samples_per_pixel, int(integrator.size()), integrator.data(),
           image.max_depth);
    std::string shapes;
    for (const auto& [shape, n] : s.objects_by_shape)
        shapes += (shapes.empty() ? ": " : ", ") + shape + " " + std::to_string(n);
    append(out, "Objects      %zu%s\n", s.objects, shapes.c_str());
    append(out, "Triangles    %zu\n", s.triangles);
    append(out, "Materials    %zu\n", s.materials);
    append(out, "Lights       %s\n", lights_text(s).c_str());
    if (s.animation)
        append(out, "Animation    %d frames at %g fps (%g s; frame 0 is described here); %zu %s\n",
               s.animation->frames, double(s.animation->fps),
               double(s.animation->frames) / double(s.animation->fps), s.moving_lights,
               s.moving_lights == 1 ? "light moves" : "lights move");
    if (s.sky_width > 0)
        append(out, "Sky          an image of %dx%d pixels: %s\n", s.sky_width, s.sky_height,
               integrator_info(image.integrator).physically_based
                   ? "it lights the scene"
                   : "seen only (this integrator's light is the ambient term)");
    if (s.bounds.is_empty())
        append(out, "Bounds       none (no bounded objects)");
    else
        append(out, "Bounds       %s to %s", point_text(s.bounds.min).c_str(),
               point_text(s.bounds.max).c_str());
    if (s.unbounded_objects > 0)
        append(out, "; %s",
               plural(s.unbounded_objects, "unbounded object (a plane) beside",
                      "unbounded objects (planes) beside")
                   .c_str());
    out += "\n";
    accel_text(out, r.accel, r.accel_stats);
    std::size_t warnings = 0;
    for (const LintWarning& w : r.warnings) warnings += !w.note;
    if (warnings == 0) out += "\nNo warnings\n";
    // Warnings first, then notes.
    for (const bool notes : {false, true}) {
        const std::size_t n = notes ? r.warnings.size() - warnings : warnings;
        if (n == 0) continue;
        append(
            out, "\n%s\n",
            notes ? plural(n, "note", "notes").c_str() : plural(n, "warning", "warnings").c_str());
        for (const LintWarning& w : r.warnings)
            if (w.note == notes)
                out += wrapped("  " + where(w) + w.subject + ": " + w.message + " [" +
                               std::string(w.rule) + "]");
    }
    return out;
}

std::string info_json(const InfoReport& r) {
    const SceneSummary& s = r.summary;
    const AccelStats& a = r.accel_stats;
    std::string out = "{\n";
    out += "  \"scene\": " + json_string(r.scene) + ",\n";
    append(out,
           "  \"image\": {\"width\": %d, \"height\": %d, \"samples_per_pixel\": %d, "
           "\"integrator\": %s, \"max_depth\": %d},\n",
           r.settings.width, r.settings.height, r.settings.samples_per_pixel,
           json_string(integrator_name(r.settings.integrator)).c_str(), r.settings.max_depth);
    append(out, "  \"objects\": {\"total\": %zu, \"by_shape\": {", s.objects);
    const char* separator = "";
    for (const auto& [shape, n] : s.objects_by_shape) {
        append(out, "%s%s: %zu", separator, json_string(shape).c_str(), n);
        separator = ", ";
    }
    out += "}},\n";
    append(out, "  \"triangles\": %zu,\n  \"materials\": %zu,\n", s.triangles, s.materials);
    append(out,
           "  \"lights\": {\"point\": %zu, \"spot\": %zu, \"directional\": %zu, \"area\": %zu, "
           "\"emitting_objects\": %zu},\n",
           s.point_lights, s.spot_lights, s.directional_lights, s.area_lights, s.emitting_objects);
    if (s.animation)
        append(out, "  \"animation\": {\"frames\": %d, \"fps\": %.9g, \"moving_lights\": %zu},\n",
               s.animation->frames, double(s.animation->fps), s.moving_lights);
    else
        out += "  \"animation\": null,\n";
    if (s.sky_width > 0)
        append(out, "  \"sky\": {\"width\": %d, \"height\": %d},\n", s.sky_width, s.sky_height);
    else
        out += "  \"sky\": null,\n";
    if (s.bounds.is_empty())
        append(out, "  \"bounds\": {\"min\": null, \"max\": null, \"unbounded_objects\": %zu},\n",
               s.unbounded_objects);
    else
        append(out, "  \"bounds\": {\"min\": %s, \"max\": %s, \"unbounded_objects\": %zu},\n",
               point_json(s.bounds.min).c_str(), point_json(s.bounds.max).c_str(),
               s.unbounded_objects);
    append(out, "  \"accel\": {\n    \"name\": %s,\n    \"available\": %s,\n",
           json_string(r.accel).c_str(), a.available ? "true" : "false");
    append(out,
           "    \"interior_nodes\": %zu,\n    \"leaves\": %zu,\n    \"empty_leaves\": %zu,\n"
           "    \"max_depth\": %d,\n    \"mean_leaf_depth\": %.6g,\n",
           a.interior_nodes, a.leaves, a.empty_leaves, a.max_depth, a.mean_leaf_depth);
    append(out,
           "    \"min_leaf_size\": %zu,\n    \"mean_leaf_size\": %.6g,\n"
           "    \"max_leaf_size\": %zu,\n    \"references\": %zu,\n    \"unbounded\": %zu,\n",
           a.min_leaf_size, a.mean_leaf_size, a.max_leaf_size, a.references, a.unbounded);
    append(out,
           "    \"sah_cost\": %.6g,\n    \"sah_traversal_cost\": %g,\n"
           "    \"sah_intersection_cost\": %g,\n    \"memory_bytes\": %zu\n  },\n",
           a.sah_cost, kSahTraversalCost, kSahIntersectionCost, a.memory_bytes);
    out += "  \"warnings\": [";
    separator = "\n";
    for (const LintWarning& w : r.warnings) {
        append(out, "%s    {\"rule\": %s, \"severity\": \"%s\", \"subject\": %s, ", separator,
               json_string(w.rule).c_str(), w.note ? "note" : "warning",
               json_string(w.subject).c_str());
        out += "\"message\": " + json_string(w.message) + ", ";
        if (w.location)
            out += "\"file\": " + json_string(w.location->file) +
                   ", \"line\": " + std::to_string(w.location->line) +
                   ", \"column\": " + std::to_string(w.location->column) + "}";
        else
            out += "\"file\": null, \"line\": null, \"column\": null}";
        separator = ",\n";
    }
    out += r.warnings.empty() ? "]\n" : "\n  ]\n";
    out += "}\n";
    return out;
}

}  // namespace glint::cli
