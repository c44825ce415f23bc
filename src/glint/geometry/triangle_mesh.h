// A triangle mesh: shared, immutable vertex and index arrays with a BVH over the triangles, and
// the shape that intersects it. Building validates the arrays and drops degenerate triangles.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "glint/geometry/bvh4_traversal.h"
#include "glint/geometry/surface_point.h"
#include "glint/math/bounds.h"
#include "glint/math/interval.h"
#include "glint/math/ray.h"

namespace glint {

// Immutable once built; shared by every object that uses it. Triangles run counter-clockwise
// seen from their front side, as for Triangle.
struct MeshData {
    std::vector<Point3> positions;
    std::vector<Normal3> normals;  // unit, one per position; or empty for flat shading
    std::vector<Point2> uvs;       // one per position; or empty
    std::vector<std::array<std::uint32_t, 3>> triangles;
    Bvh4 bvh;  // over triangles; made by build_mesh
};

// Whether every edge joins exactly two triangles that run along it in opposite directions
// (vertices matched by position): the mesh bounds a solid, usable as a CSG operand. O(N log N);
// asked only of CSG operands, not of every mesh loaded.
bool is_closed_surface(const MeshData& mesh);

// Coordinates beyond this magnitude are refused: products of such edges overflow a float.
inline constexpr float kMaxMeshCoordinate = 1e16f;
// More triangles or vertices than this are refused (indices are 32-bit).
inline constexpr std::size_t kMaxMeshElements = std::size_t(1) << 31;

struct MeshBuild {
    std::shared_ptr<const MeshData> mesh;  // null on error
    std::string error;                     // why, when mesh is null
    std::size_t degenerate_dropped = 0;    // triangles of zero area or with a repeated index
};

// Validates the arrays (normals and uvs empty or one per position, indices in range, every
// coordinate finite and within kMaxMeshCoordinate), normalises the normals, drops degenerate
// triangles (counted in the result), and builds the BVH. The bvh field of `arrays` is ignored.
// Errors are messages, never exceptions: "triangle 7 uses vertex 12 but there are 10 vertices".
MeshBuild build_mesh(MeshData arrays);

struct TriangleMesh {
    std::shared_ptr<const MeshData> data;  // built by build_mesh; never null

    Bounds3 bounds() const { return data->bvh.bounds(); }
    // Nearest hit: the BVH, then Moeller-Trumbore on each triangle (as Triangle does).
    // hit.part is the triangle's index, hit.u and hit.v the barycentric weights of its
    // vertices 1 and 2.
    std::optional<ShapeHit> intersect(const Ray& ray, Interval t_range) const;
    // Whether any triangle is hit within t_range; stops at the first.
    bool occluded(const Ray& ray, Interval t_range) const;
    // The normal follows the triangle's winding; the shading normal interpolates the vertex
    // normals when there are any (turned to the normal's side); uv interpolates the vertex uvs,
    // or is the barycentric (u, v) without them.
    SurfacePoint surface_at(const Ray& ray, const ShapeHit& hit) const;
};

// Moeller and Trumbore (1997) on the mesh's triangle `index`; two-sided.
std::optional<ShapeHit> intersect_triangle(const MeshData& mesh, std::uint32_t index,
                                           const Ray& ray, Interval t_range);

}  // namespace glint
