// Each segment is cut at a plane just in front of the eye, then projected through the pinhole
// frame as beam tracing projects its polygons (Camera::Pinhole).
#include "glint/render/explain/ray_tree_overlay.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include "glint/camera/camera.h"

namespace glint {

namespace {

struct Projector {
    Camera::Pinhole frame;
    float width, height;
    float near;  // the cutting plane's distance from the eye, along the view

    float depth(Point3 p) const { return dot(p - frame.eye, frame.n); }
    Point2 film(Point3 p) const {
        const Vector3 d = p - frame.eye;
        const float z = dot(d, frame.n);
        return {(dot(d, frame.u) / z / frame.half_width + 1) * width / 2,
                (1 - dot(d, frame.v) / z / frame.half_height) * height / 2};
    }
    // The part of a to b in front of the eye, projected; none when all of it is behind.
    std::optional<std::pair<Point2, Point2>> segment(Point3 a, Point3 b) const {
        const float za = depth(a), zb = depth(b);
        if (za < near && zb < near) return std::nullopt;
        const auto cut = [&](Point3 behind, float z_behind, Point3 front, float z_front) {
            const float s = (near - z_behind) / (z_front - z_behind);
            return behind + (front - behind) * s;
        };
        if (za < near) a = cut(a, za, b, zb);
        if (zb < near) b = cut(b, zb, a, za);
        return std::pair{film(a), film(b)};
    }
};

bool any_below_one(Color c) { return c.r < 1 || c.g < 1 || c.b < 1; }

}  // namespace

std::vector<OverlaySegment> ray_tree_overlay(const RayTree& tree, const CameraSpec& spec, int width,
                                             int height, float reach) {
    std::vector<OverlaySegment> segments;
    if (spec.projection != Projection::perspective || !spec.motion.empty()) return segments;
    const Camera camera(spec, width, height);
    // Near enough that nothing the scene shows is cut, far enough to keep the division exact.
    const Projector projector{camera.pinhole(), float(width), float(height), reach * 1e-6f};
    const auto add = [&](OverlaySegment s, Point3 a, Point3 b) {
        if (const auto ends = projector.segment(a, b)) {
            s.from = ends->first;
            s.to = ends->second;
            segments.push_back(s);
        }
    };
    for (std::size_t i = 0; i < tree.nodes.size(); ++i) {
        const RayNode& node = tree.nodes[i];
        const bool missed = node.stop == StopReason::missed;
        OverlaySegment ray{int(i), node.kind};
        ray.missed = missed;
        add(ray, node.ray.origin,
            missed ? node.ray.origin + node.ray.direction * reach : node.point);
        if (missed) continue;
        const auto feeler = [&](int light, Vector3 to_light, float distance, Color shadow) {
            OverlaySegment s{int(i), RayKind::shadow, light, any_below_one(shadow)};
            add(s, node.point,
                node.point + to_light * (std::isfinite(distance) ? distance : reach));
        };
        for (std::size_t l = 0; l < node.lights.size(); ++l)
            for (const LightSampleRecord& sample : node.lights[l].samples)
                if (sample.faces_light && !sample.shadow_map)
                    feeler(int(l), sample.to_light, sample.distance, sample.shadow);
        if (node.path)
            for (std::size_t l = 0; l < node.path->next_events.size(); ++l) {
                const NextEventRecord& event = node.path->next_events[l];
                if (!is_black(event.f))  // the feeler is traced only then
                    feeler(int(l), event.to_light, event.distance, event.shadow);
            }
    }
    return segments;
}

}  // namespace glint
