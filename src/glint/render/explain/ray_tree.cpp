// A ray tree's colour worked out again from its terms, in the integrators' order of operations.
#include "glint/render/explain/ray_tree.h"

namespace glint {

std::string_view stop_reason_name(StopReason reason) {
    switch (reason) {
        case StopReason::none:
            return "none";
        case StopReason::missed:
            return "missed";
        case StopReason::max_depth:
            return "maximum depth";
        case StopReason::min_weight:
            return "minimum weight";
        case StopReason::blocked_by_surface:
            return "blocked by the surface";
        case StopReason::total_internal_reflection:
            return "total internal reflection";
        case StopReason::roulette:
            return "Russian roulette";
    }
    return "?";
}

namespace {

// A light's share: its one sample's term, or the mean of its samples' terms.
Color light_value(const LightRecord& light) {
    if (!light.averaged) return light.samples.empty() ? Color{} : light.samples[0].term;
    Color sum;
    for (const LightSampleRecord& s : light.samples) sum += s.term;
    return sum / float(light.samples.size());
}

}  // namespace

Color evaluate(const RayTree& tree, int index) {
    const RayNode& n = tree.nodes[std::size_t(index)];
    if (n.stop == StopReason::missed) return through(n.fog, n.background);
    Color color = n.emission + n.ambient;
    for (const LightRecord& light : n.lights) color += light_value(light);
    for (const BranchRecord& b : n.branches)
        if (b.child >= 0) color += b.factor * evaluate(tree, b.child);
    return through(n.fog, color);
}

Color evaluate(const RayTree& tree) { return tree.nodes.empty() ? Color{} : evaluate(tree, 0); }

Color contribution(const RayNode& node) {
    const Color own = node.stop == StopReason::missed ? node.background
                                                      : node.emission + node.ambient + node.direct;
    return node.throughput * through(node.fog, own);
}

}  // namespace glint
