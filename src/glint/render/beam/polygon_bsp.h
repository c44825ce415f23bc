// A binary space partitioning tree of polygons (Fuchs, Kedem and Naylor 1980), built once over a
// scene's polygons by splitting them on each other's planes: from any point of view it lists the
// pieces in an order in which none is hidden by a later one. Beam tracing takes each beam's
// polygons in this order from the beam's virtual eye, so cyclic overlaps and polygons that pierce
// each other are cut where they must be, where the paper's depth sort assumed they do not occur.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "glint/render/beam/beam_polygons.h"

namespace glint::beam {

// A part of polygons[polygon], in that polygon's frame.
struct BspPiece {
    std::uint32_t polygon;
    Paths region;
};

class PolygonBsp {
public:
    PolygonBsp() = default;  // no pieces
    // Points within `tolerance` (scene units) of a plane count as on it.
    PolygonBsp(std::span<const BeamPolygon> polygons, double tolerance);

    // Calls visit(piece) for each piece, nearest to `eye` first, until visit returns false,
    // skipping the subtrees whose bounding box lies wholly behind one of `bounds` (on its
    // negative side). Returns whether it went through to the end.
    template <class F>
    bool front_to_back(Vector3d eye, std::span<const PlaneD> bounds, F&& visit) const {
        return visit_node(root_, eye, bounds, visit);
    }
    template <class F>
    bool front_to_back(Vector3d eye, F&& visit) const {
        return visit_node(root_, eye, {}, visit);
    }
    std::size_t piece_count() const { return pieces_; }
    std::size_t node_count() const { return nodes_.size(); }

private:
    struct Node {
        PlaneD plane;
        std::vector<BspPiece> on;  // in the plane
        int front = -1, back = -1;
        Vector3d low, high;  // the bounding box of every piece below
    };
    static bool outside(const Node& node, std::span<const PlaneD> bounds) {
        for (const PlaneD& b : bounds) {
            // The box's corner furthest along the plane's normal.
            const Vector3d far{b.n.x >= 0 ? node.high.x : node.low.x,
                               b.n.y >= 0 ? node.high.y : node.low.y,
                               b.n.z >= 0 ? node.high.z : node.low.z};
            if (b.at(far) < 0) return true;
        }
        return false;
    }
    int build(std::vector<BspPiece> pieces, std::span<const BeamPolygon> polygons,
              double tolerance);
    template <class F>
    bool visit_node(int index, Vector3d eye, std::span<const PlaneD> bounds, F& visit) const {
        if (index < 0) return true;
        const Node& node = nodes_[std::size_t(index)];
        if (outside(node, bounds)) return true;
        const bool eye_in_front = node.plane.at(eye) >= 0;
        if (!visit_node(eye_in_front ? node.front : node.back, eye, bounds, visit)) return false;
        for (const BspPiece& piece : node.on)
            if (!visit(piece)) return false;
        return visit_node(eye_in_front ? node.back : node.front, eye, bounds, visit);
    }

    std::vector<Node> nodes_;
    int root_ = -1;
    std::size_t pieces_ = 0;
};

}  // namespace glint::beam
