// Polygons, triangles, meshes and boxes, through their transforms, as planar regions.
#include "glint/render/beam/beam_polygons.h"

#include <cmath>

#include "glint/render/world.h"

namespace glint::beam {

namespace {

Vector3d unit(Vector3d v) { return v * (1 / std::sqrt(dot(v, v))); }

struct Collector {
    double scale;
    std::uint32_t primitive;
    bool seen, casts_shadows;
    std::vector<BeamPolygon>& out;

    // A polygon of world-space vertices with its outward unit normal.
    BeamPolygon& add(const std::vector<Vector3d>& vertices, Vector3d normal, bool even_odd,
                     std::uint32_t part) {
        BeamPolygon p;
        p.frame = frame_of_plane(vertices[0], unit(normal), scale);
        Path outline;
        for (const Vector3d& v : vertices) outline.push_back(p.frame.local(v));
        p.region = simplified({outline}, even_odd);
        p.plane = {p.frame.n, dot(p.frame.n, vertices[0])};
        p.primitive = primitive;
        p.part = part;
        p.seen = seen;
        p.casts_shadows = casts_shadows;
        out.push_back(std::move(p));
        return out.back();
    }
    void add_triangle(const Transform* t, Point3 a, Point3 b, Point3 c, std::uint32_t part) {
        const Vector3d v[3] = {place(t, a), place(t, b), place(t, c)};
        const Vector3d n = cross(v[1] - v[0], v[2] - v[0]);
        if (dot(n, n) == 0) return;
        BeamPolygon& p = add({v[0], v[1], v[2]}, n, false, part);
        p.barycentric = true;
        p.corners = {v[0], v[1], v[2]};
    }
    static Vector3d place(const Transform* t, Point3 p) { return Vector3d(t ? (*t)(p) : p); }
    static Vector3d place_normal(const Transform* t, Normal3 n) {
        const Normal3 m = t ? (*t)(n) : n;
        return {m.x, m.y, m.z};
    }

    void collect(const Shape& shape, const Transform* t) {
        if (const auto* p = std::get_if<Polygon>(&shape)) {
            std::vector<Vector3d> v;
            for (Point3 q : p->vertices) v.push_back(place(t, q));
            add(v, place_normal(t, p->normal), p->inside_test == InsideTest::even_odd, 0);
        } else if (const auto* tri = std::get_if<Triangle>(&shape)) {
            add_triangle(t, tri->vertices[0], tri->vertices[1], tri->vertices[2], 0);
        } else if (const auto* mesh = std::get_if<TriangleMesh>(&shape)) {
            const MeshData& data = *mesh->data;
            for (std::size_t i = 0; i < data.triangles.size(); ++i) {
                const auto& k = data.triangles[i];
                add_triangle(t, data.positions[k[0]], data.positions[k[1]], data.positions[k[2]],
                             std::uint32_t(i));
            }
        } else if (const auto* box = std::get_if<Box>(&shape)) {
            // Face 2 axis + side, as Box's hits name them, wound outwards.
            for (int axis = 0; axis < 3; ++axis)
                for (int side = 0; side < 2; ++side) {
                    const int a = (axis + 1) % 3, b = (axis + 2) % 3;
                    std::vector<Vector3d> v;
                    const float corners[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
                    for (const auto& c : corners) {
                        float q[3];
                        q[axis] = side ? box->max[axis] : box->min[axis];
                        q[a] = c[0] != 0 ? box->max[a] : box->min[a];
                        q[b] = c[1] != 0 ? box->max[b] : box->min[b];
                        v.push_back(place(t, Point3{q[0], q[1], q[2]}));
                    }
                    float n[3] = {0, 0, 0};
                    n[axis] = side ? 1.0f : -1.0f;
                    add(v, place_normal(t, Normal3{n[0], n[1], n[2]}), false,
                        std::uint32_t(2 * axis + side));
                }
        } else if (const auto* placed = std::get_if<Transformed>(&shape)) {
            const Transform whole =
                t ? Transform(*t * placed->world_from_object()) : placed->world_from_object();
            collect(*placed->shape, &whole);
        }
    }
};

}  // namespace

std::vector<BeamPolygon> beam_polygons(const World& world, double scale) {
    std::vector<BeamPolygon> out;
    const auto primitives = world.primitives();
    for (std::size_t i = 0; i < primitives.size(); ++i) {
        if (!(primitives[i].visibility & kVisibleToCameraRays) &&
            !(primitives[i].visibility & kVisibleToShadowRays))
            continue;
        Collector c{scale, std::uint32_t(i), (primitives[i].visibility & kVisibleToCameraRays) != 0,
                    (primitives[i].visibility & kVisibleToShadowRays) != 0, out};
        c.collect(primitives[i].shape, nullptr);
    }
    return out;
}

}  // namespace glint::beam
