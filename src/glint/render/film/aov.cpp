#include "glint/render/film/aov.h"

#include <algorithm>
#include <stdexcept>

#include "glint/geometry/traversal_counters.h"

namespace glint {

namespace {

using enum AovKind;
constexpr std::array<AovInfo, kAovCount> kAovs = {{
    {"depth", surface, 1, {"Z"}, "distance along the eye ray to its hit"},
    {"position", surface, 3, {"X", "Y", "Z"}, "the hit point, world space"},
    {"normal", surface, 3, {"X", "Y", "Z"}, "the shading normal, facing the eye"},
    {"albedo", surface, 3, {"R", "G", "B"}, "the surface colour C at the hit"},
    {"uv", surface, 2, {"U", "V"}, "texture coordinates at the hit"},
    {"object", id, 1, {"id"}, "scene index of the object hit"},
    {"material", id, 1, {"id"}, "scene index of its material"},
    {"emission", sample_mean, 3, {"R", "G", "B"}, "emission or background seen directly"},
    {"ambient", sample_mean, 3, {"R", "G", "B"}, "ka Ia C at the hit"},
    {"diffuse", sample_mean, 3, {"R", "G", "B"}, "the lights' diffuse terms, shadowed"},
    {"specular", sample_mean, 3, {"R", "G", "B"}, "the lights' highlight terms, shadowed"},
    {"reflected", sample_mean, 3, {"R", "G", "B"}, "kr I(reflected)"},
    {"refracted", sample_mean, 3, {"R", "G", "B"}, "kt I(refracted)"},
    {"direct", sample_mean, 3, {"R", "G", "B"}, "light straight from emitters (path)"},
    {"indirect", sample_mean, 3, {"R", "G", "B"}, "light scattered on its way (path)"},
    {"fog", sample_mean, 3, {"R", "G", "B"}, "light the fog adds along the eye ray"},
    {"tree_depth", sample_mean, 1, {"Y"}, "depth of the ray tree, 1 for the eye ray alone"},
    {"samples", pixel, 1, {"Y"}, "samples the pixel took"},
    {"nodes", sample_mean, 1, {"Y"}, "acceleration nodes visited per sample"},
    {"primitives", sample_mean, 1, {"Y"}, "primitives tested per sample"},
}};

void add_range(AovSet& set, Aov first, Aov last) {
    for (auto a = unsigned(first); a <= unsigned(last); ++a) set.add(Aov(a));
}

}  // namespace

const AovInfo& aov_info(Aov aov) { return kAovs[std::size_t(aov)]; }

bool counts_traversal() { return kCountTraversal; }

std::vector<Aov> AovSet::list() const {
    std::vector<Aov> out;
    for (std::size_t a = 0; a < kAovCount; ++a)
        if (has(Aov(a))) out.push_back(Aov(a));
    return out;
}

AovSet parse_aov_list(std::string_view list) {
    AovSet set;
    std::size_t start = 0;
    while (start <= list.size()) {
        const std::size_t comma = std::min(list.find(',', start), list.size());
        const std::string_view name = list.substr(start, comma - start);
        start = comma + 1;
        if (name == "contributions") {
            add_range(set, Aov::emission, Aov::fog);
        } else if (name == "surface") {
            add_range(set, Aov::depth, Aov::uv);
        } else if (name == "ids") {
            add_range(set, Aov::object, Aov::material);
        } else if (name == "cost") {
            add_range(set, Aov::nodes, Aov::primitives);
        } else if (name == "all") {
            add_range(set, Aov::depth, Aov::samples);
            if (counts_traversal()) add_range(set, Aov::nodes, Aov::primitives);
        } else {
            std::size_t a = 0;
            while (a < kAovCount && kAovs[a].name != name) ++a;
            if (a == kAovCount)
                throw std::invalid_argument(
                    "unknown output variable '" + std::string(name) +
                    "' (depth, position, normal, albedo, uv, object, material, emission, ambient, "
                    "diffuse, specular, reflected, refracted, direct, indirect, fog, tree_depth, "
                    "samples, nodes, primitives; or contributions, surface, ids, cost, all)");
            set.add(Aov(a));
        }
    }
    if ((set.has(Aov::nodes) || set.has(Aov::primitives)) && !counts_traversal())
        throw std::invalid_argument(
            "this glint was built without traversal counters, so it cannot write nodes or "
            "primitives: configure with -DGLINT_TRAVERSAL_COUNTERS=ON (the debug and asan presets "
            "do)");
    return set;
}

Color AovSample::value(Aov a) const {
    switch (a) {
        case Aov::depth:
            return Color::gray(depth);
        case Aov::position:
            return {position.x, position.y, position.z};
        case Aov::normal:
            return {normal.x, normal.y, normal.z};
        case Aov::albedo:
            return albedo;
        case Aov::uv:
            return {uv.x, uv.y, 0};
        case Aov::object:
            return Color::gray(float(object));
        case Aov::material:
            return Color::gray(float(material));
        case Aov::emission:
            return emission;
        case Aov::ambient:
            return ambient;
        case Aov::diffuse:
            return diffuse;
        case Aov::specular:
            return specular;
        case Aov::reflected:
            return reflected;
        case Aov::refracted:
            return refracted;
        case Aov::direct:
            return direct;
        case Aov::indirect:
            return indirect;
        case Aov::fog:
            return fog;
        case Aov::tree_depth:
            return Color::gray(float(tree_depth));
        case Aov::samples:
            return {};
        case Aov::nodes:
            return Color::gray(float(nodes));
        case Aov::primitives:
            return Color::gray(float(primitives));
    }
    return {};
}

}  // namespace glint
