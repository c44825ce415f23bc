// Building meshes (validation, degenerate triangles) and intersecting them.
#include "glint/geometry/triangle_mesh.h"

#include <cmath>
#include <numeric>
#include <string>

#include "glint/geometry/traversal_counters.h"
#include "glint/geometry/triangle.h"
#include "glint/geometry/triangle_derivatives.h"

namespace glint {

namespace {

bool in_range(float c) { return std::isfinite(c) && std::abs(c) <= kMaxMeshCoordinate; }

std::string coordinate_error(const char* what, std::size_t index, float x, float y, float z) {
    return std::string(what) + " " + std::to_string(index) +
           " has a coordinate that is not finite " + "or beyond +-1e16: (" + std::to_string(x) +
           ", " + std::to_string(y) + ", " + std::to_string(z) + ")";
}

// The unit vector along v, computed after scaling by the largest component so that tiny or huge
// cross products neither underflow nor overflow. Zero stays zero.
Vector3 robust_normalize(Vector3 v) {
    const float m = max_component(abs(v));
    if (!(m > 0) || !std::isfinite(m)) return {};
    return normalize(v / m);
}

Vector3 face_cross(const MeshData& mesh, std::uint32_t index) {
    const auto& t = mesh.triangles[index];
    const Point3 a = mesh.positions[t[0]], b = mesh.positions[t[1]], c = mesh.positions[t[2]];
    return cross(b - a, c - a);
}

}  // namespace

MeshBuild build_mesh(MeshData arrays) {
    MeshBuild result;
    const std::size_t n = arrays.positions.size();
    if (n > kMaxMeshElements || arrays.triangles.size() > kMaxMeshElements) {
        result.error = "mesh has more than 2^29 - 1 vertices or triangles";
        return result;
    }
    if (!arrays.normals.empty() && arrays.normals.size() != n) {
        result.error = "mesh has " + std::to_string(arrays.normals.size()) + " normals for " +
                       std::to_string(n) + " vertices";
        return result;
    }
    if (!arrays.uvs.empty() && arrays.uvs.size() != n) {
        result.error = "mesh has " + std::to_string(arrays.uvs.size()) + " uvs for " +
                       std::to_string(n) + " vertices";
        return result;
    }
    for (std::size_t i = 0; i < n; ++i) {
        const Point3 p = arrays.positions[i];
        if (!in_range(p.x) || !in_range(p.y) || !in_range(p.z)) {
            result.error = coordinate_error("vertex", i, p.x, p.y, p.z);
            return result;
        }
    }
    for (std::size_t i = 0; i < arrays.normals.size(); ++i) {
        Normal3& m = arrays.normals[i];
        if (!std::isfinite(m.x) || !std::isfinite(m.y) || !std::isfinite(m.z)) {
            result.error = coordinate_error("normal", i, m.x, m.y, m.z);
            return result;
        }
        // A zero normal stays zero; surface_at then falls back to the geometric normal.
        m = Normal3(robust_normalize(to_vector(m)));
    }
    for (std::size_t i = 0; i < arrays.uvs.size(); ++i) {
        const Point2 uv = arrays.uvs[i];
        if (!std::isfinite(uv.x) || !std::isfinite(uv.y)) {
            result.error = coordinate_error("uv", i, uv.x, uv.y, 0);
            return result;
        }
    }
    std::size_t kept = 0;
    for (std::size_t i = 0; i < arrays.triangles.size(); ++i) {
        const auto t = arrays.triangles[i];
        for (const std::uint32_t v : t) {
            if (v >= n) {
                result.error = "triangle " + std::to_string(i) + " uses vertex " +
                               std::to_string(v) + " but there are " + std::to_string(n) +
                               " vertices";
                return result;
            }
        }
        arrays.triangles[kept] = t;
        // Zero area (repeated index, collinear or coincident corners): no ray can hit it and it
        // has no normal, so it is dropped rather than carried into the BVH.
        const Vector3 c = face_cross(arrays, std::uint32_t(kept));
        if (c.x == 0 && c.y == 0 && c.z == 0) {
            ++result.degenerate_dropped;
        } else {
            ++kept;
        }
    }
    arrays.triangles.resize(kept);
    if (kept == 0) {
        result.error = result.degenerate_dropped == 0
                           ? "mesh has no triangles"
                           : "mesh has no triangles left after dropping " +
                                 std::to_string(result.degenerate_dropped) + " degenerate ones";
        return result;
    }

    arrays.bounds = {};
    for (const auto& t : arrays.triangles)
        for (const std::uint32_t v : t) arrays.bounds = merge(arrays.bounds, arrays.positions[v]);
    result.mesh = std::make_shared<const MeshData>(std::move(arrays));
    return result;
}

bool is_closed_surface(const MeshData& mesh) {
    // Vertices that share a position are one vertex: files split them for normals and uvs.
    // Sorting (not a map) keeps this a small part of loading a million-triangle mesh.
    const auto key = [&](std::uint32_t i) {
        const Point3 p = mesh.positions[i];
        return std::array<float, 3>{p.x, p.y, p.z};
    };
    std::vector<std::uint32_t> by_position(mesh.positions.size());
    std::iota(by_position.begin(), by_position.end(), 0u);
    std::sort(by_position.begin(), by_position.end(),
              [&](std::uint32_t a, std::uint32_t b) { return key(a) < key(b); });
    std::vector<std::uint32_t> id(mesh.positions.size());
    std::uint32_t next_id = 0;
    for (std::size_t k = 0; k < by_position.size(); ++k) {
        if (k > 0 && key(by_position[k]) != key(by_position[k - 1])) ++next_id;
        id[by_position[k]] = next_id;
    }
    // Closed and oriented: each directed edge occurs once, and so does its reverse.
    const auto edge = [](std::uint32_t from, std::uint32_t to) {
        return (std::uint64_t(from) << 32) | to;
    };
    std::vector<std::uint64_t> edges;
    edges.reserve(3 * mesh.triangles.size());
    for (const auto& t : mesh.triangles)
        for (int k = 0; k < 3; ++k) edges.push_back(edge(id[t[k]], id[t[(k + 1) % 3]]));
    std::sort(edges.begin(), edges.end());
    if (std::adjacent_find(edges.begin(), edges.end()) != edges.end()) return false;
    for (const std::uint64_t e : edges)
        if (!std::binary_search(edges.begin(), edges.end(),
                                edge(std::uint32_t(e), std::uint32_t(e >> 32))))
            return false;
    return true;
}

std::optional<ShapeHit> intersect_triangle(const MeshData& mesh, std::uint32_t index,
                                           const Ray& ray, Interval t_range) {
    const auto& tri = mesh.triangles[index];
    auto hit = intersect_triangle(mesh.positions[tri[0]], mesh.positions[tri[1]],
                                  mesh.positions[tri[2]], ray, t_range);
    if (hit) hit->part = index;
    return hit;
}

std::optional<ShapeHit> TriangleMesh::intersect(const Ray& ray, Interval t_range) const {
    if (accelerator) return accelerator->intersect(ray, t_range);
    std::optional<ShapeHit> nearest;
    for (std::uint32_t i = 0; i < data->triangles.size(); ++i) {
        count_primitives();
        // Strictly nearer only: at equal t the lower triangle stays.
        if (auto hit = intersect_triangle(*data, i, ray, t_range)) {
            t_range.max = hit->t;
            if (!nearest || hit->t < nearest->t) nearest = hit;
        }
    }
    return nearest;
}

bool TriangleMesh::occluded(const Ray& ray, Interval t_range) const {
    if (accelerator) return accelerator->occluded(ray, t_range);
    for (std::uint32_t i = 0; i < data->triangles.size(); ++i) {
        count_primitives();
        if (intersect_triangle(*data, i, ray, t_range)) return true;
    }
    return false;
}

SurfacePoint TriangleMesh::surface_at(const Ray&, const ShapeHit& hit, Uv uv) const {
    const MeshData& mesh = *data;
    const auto& tri = mesh.triangles[hit.part];
    const float b0 = 1 - hit.u - hit.v;
    const Point3 p0 = mesh.positions[tri[0]], p1 = mesh.positions[tri[1]],
                 p2 = mesh.positions[tri[2]];
    SurfacePoint sp;
    // The barycentric point lies in the triangle's plane, unlike origin + t * direction.
    sp.p = to_point(to_vector(p0) * b0 + to_vector(p1) * hit.u + to_vector(p2) * hit.v);
    sp.normal = Normal3(robust_normalize(cross(p1 - p0, p2 - p0)));
    sp.shading_normal = sp.normal;
    if (!mesh.normals.empty()) {
        const Vector3 n = to_vector(mesh.normals[tri[0]]) * b0 +
                          to_vector(mesh.normals[tri[1]]) * hit.u +
                          to_vector(mesh.normals[tri[2]]) * hit.v;
        const Vector3 unit = robust_normalize(n);
        const float side = dot(sp.normal, unit);
        // Normals that disagree with the winding are turned over; one in the surface's plane (or
        // interpolated to zero) says nothing, and the geometric normal stands in.
        if (side != 0 && std::isfinite(side)) {
            sp.shading_normal = Normal3(side > 0 ? unit : -unit);
        }
    }
    std::array<Point2, 3> uvs{{{0, 0}, {1, 0}, {0, 1}}};
    if (!mesh.uvs.empty()) uvs = {mesh.uvs[tri[0]], mesh.uvs[tri[1]], mesh.uvs[tri[2]]};
    sp.uv = {b0 * uvs[0].x + hit.u * uvs[1].x + hit.v * uvs[2].x,
             b0 * uvs[0].y + hit.u * uvs[1].y + hit.v * uvs[2].y};
    if (uv == Uv::skip) return sp;
    const UvDerivatives dp = uv_derivatives({to_vector(p0), to_vector(p1), to_vector(p2)}, uvs);
    sp.dpdu = dp.du;
    sp.dpdv = dp.dv;
    // The interpolated normal's change, left unnormalised (as pbrt does): enough for a pencil's
    // spread, and zero on a flat-shaded mesh.
    if (!mesh.normals.empty()) {
        const float side = dot(sp.normal, sp.shading_normal) < 0 ? -1.0f : 1.0f;
        const UvDerivatives dn = uv_derivatives(
            {to_vector(mesh.normals[tri[0]]) * side, to_vector(mesh.normals[tri[1]]) * side,
             to_vector(mesh.normals[tri[2]]) * side},
            uvs);
        sp.dndu = dn.du;
        sp.dndv = dn.dv;
    }
    sp.has_derivatives = true;
    return sp;
}

float TriangleMesh::area() const {
    double sum = 0;
    for (const auto& tri : data->triangles)
        sum += 0.5 * double(length(cross(data->positions[tri[1]] - data->positions[tri[0]],
                                         data->positions[tri[2]] - data->positions[tri[0]])));
    return float(sum);
}

}  // namespace glint
