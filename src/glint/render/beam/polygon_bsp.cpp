// Autopartition: each node splits on the plane of one of its polygons, the one of a few
// candidates that cuts the fewest others.
#include "glint/render/beam/polygon_bsp.h"

#include <algorithm>
#include <cmath>

namespace glint::beam {

PolygonBsp::PolygonBsp(std::span<const BeamPolygon> polygons, double tolerance) {
    std::vector<BspPiece> pieces;
    pieces.reserve(polygons.size());
    for (std::size_t i = 0; i < polygons.size(); ++i)
        if (!polygons[i].region.empty()) pieces.push_back({std::uint32_t(i), polygons[i].region});
    root_ = build(std::move(pieces), polygons, tolerance);
}

int PolygonBsp::build(std::vector<BspPiece> pieces, std::span<const BeamPolygon> polygons,
                      double tolerance) {
    if (pieces.empty()) return -1;
    const auto side = [&](const BspPiece& p, const PlaneD& plane) {
        return side_of(polygons[p.polygon].frame, p.region, plane, tolerance);
    };
    // Of up to five candidates spread over the list, the plane that straddles the fewest of up
    // to 64 pieces spread likewise.
    std::size_t best = 0, best_cuts = ~std::size_t{0};
    const std::size_t candidates = std::min<std::size_t>(5, pieces.size());
    const std::size_t sampled = std::min<std::size_t>(64, pieces.size());
    for (std::size_t c = 0; c < candidates && best_cuts > 0; ++c) {
        const std::size_t i = c * pieces.size() / candidates;
        const PlaneD& plane = polygons[pieces[i].polygon].plane;
        std::size_t cuts = 0;
        for (std::size_t s = 0; s < sampled; ++s)
            cuts += side(pieces[s * pieces.size() / sampled], plane) == Side::straddles;
        if (cuts < best_cuts) best = i, best_cuts = cuts;
    }
    Node node;
    node.plane = polygons[pieces[best].polygon].plane;
    std::vector<BspPiece> front, back;
    for (BspPiece& p : pieces) {
        switch (side(p, node.plane)) {
            case Side::in_plane:
                node.on.push_back(std::move(p));
                break;
            case Side::front:
                front.push_back(std::move(p));
                break;
            case Side::back:
                back.push_back(std::move(p));
                break;
            case Side::straddles: {
                const PlaneFrame& frame = polygons[p.polygon].frame;
                Paths f = clip_to_halfspace(frame, p.region, node.plane);
                Paths b = clip_to_halfspace(frame, p.region, node.plane.flipped());
                if (!f.empty()) front.push_back({p.polygon, std::move(f)});
                if (!b.empty()) back.push_back({p.polygon, std::move(b)});
                break;
            }
        }
    }
    pieces_ += node.on.size();
    node.low = {HUGE_VAL, HUGE_VAL, HUGE_VAL};
    node.high = node.low * -1.0;
    for (const BspPiece& p : node.on)
        for (const Path& ring : p.region)
            for (const IntPoint& q : ring) {
                const Vector3d w = polygons[p.polygon].frame.world(q);
                node.low = {std::min(node.low.x, w.x), std::min(node.low.y, w.y),
                            std::min(node.low.z, w.z)};
                node.high = {std::max(node.high.x, w.x), std::max(node.high.y, w.y),
                             std::max(node.high.z, w.z)};
            }
    const int index = int(nodes_.size());
    nodes_.push_back(std::move(node));
    const int f = build(std::move(front), polygons, tolerance);
    const int b = build(std::move(back), polygons, tolerance);
    Node& built = nodes_[std::size_t(index)];
    built.front = f;
    built.back = b;
    for (const int child : {f, b}) {
        if (child < 0) continue;
        const Node& c = nodes_[std::size_t(child)];
        built.low = {std::min(built.low.x, c.low.x), std::min(built.low.y, c.low.y),
                     std::min(built.low.z, c.low.z)};
        built.high = {std::max(built.high.x, c.high.x), std::max(built.high.y, c.high.y),
                      std::max(built.high.z, c.high.z)};
    }
    // A margin for the integer coordinates' rounding.
    const Vector3d margin{tolerance, tolerance, tolerance};
    built.low = built.low - margin;
    built.high = built.high + margin;
    return index;
}

}  // namespace glint::beam
