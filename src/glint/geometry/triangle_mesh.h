// A triangle mesh: shared, immutable vertex and index arrays, and the shape that intersects
// them. Building validates the arrays and drops degenerate triangles. The BVH that traces a mesh
// whole is not here but in accel/mesh_bvh.h: a scene's meshes are plain data.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "glint/geometry/surface_point.h"
#include "glint/math/bounds.h"
#include "glint/math/huge_page_allocator.h"
#include "glint/math/interval.h"
#include "glint/math/ray.h"

namespace glint {

// Immutable once built; shared by every object that uses it. Triangles run counter-clockwise
// seen from their front side, as for Triangle.
struct MeshData {
    LargeVector<Point3> positions;
    LargeVector<Normal3> normals;  // unit, one per position; or empty for flat shading
    LargeVector<Point2> uvs;       // one per position; or empty
    LargeVector<std::array<std::uint32_t, 3>> triangles;
    Bounds3 bounds;  // of the triangles; set by build_mesh
};

// Whether every edge joins exactly two triangles that run along it in opposite directions
// (vertices matched by position): the mesh bounds a solid, usable as a CSG operand. O(N log N);
// asked only of CSG operands, not of every mesh loaded.
bool is_closed_surface(const MeshData& mesh);

// Coordinates beyond this magnitude are refused: products of such edges overflow a float.
inline constexpr float kMaxMeshCoordinate = 1e16f;
// More triangles or vertices than this are refused: what a wide BVH can index (accel/wide_bvh.h,
// which checks that it does).
inline constexpr std::size_t kMaxMeshElements = 0x1fffffff;

struct MeshBuild {
    std::shared_ptr<const MeshData> mesh;  // null on error
    std::string error;                     // why, when mesh is null
    std::size_t degenerate_dropped = 0;    // triangles of zero area or with a repeated index
};

// Validates the arrays (normals and uvs empty or one per position, indices in range, every
// coordinate finite and within kMaxMeshCoordinate), normalises the normals, drops degenerate
// triangles (counted in the result), and computes the bounds. The BVH is built when first asked.
// Errors are messages, never exceptions: "triangle 7 uses vertex 12 but there are 10 vertices".
MeshBuild build_mesh(MeshData arrays);

// What traces one mesh whole, faster than triangle by triangle, with the same answers: the BVH
// over its triangles that the world builds for a mesh inside an instance, a transform, a CSG
// operand or a light buffer (accel/mesh_bvh.h). One indirect call a ray that reaches the mesh,
// which then traverses a tree over all its triangles.
class MeshAccelerator {
public:
    virtual ~MeshAccelerator() = default;
    virtual std::optional<ShapeHit> intersect(const Ray& ray, Interval t_range) const = 0;
    virtual bool occluded(const Ray& ray, Interval t_range) const = 0;
};

struct TriangleMesh {
    std::shared_ptr<const MeshData> data;  // built by build_mesh; never null
    // Set by the world for the meshes it traces whole (bind_mesh_bvhs); null in a Scene, where
    // the mesh is tested triangle by triangle: right, and only slow for big meshes.
    std::shared_ptr<const MeshAccelerator> accelerator;

    Bounds3 bounds() const { return data->bounds; }
    // Nearest hit, through the accelerator or triangle by triangle, with the watertight test (as
    // Triangle's). hit.part is the triangle's index (the lower one at equal t), hit.u and hit.v
    // the barycentric weights of its vertices 1 and 2.
    std::optional<ShapeHit> intersect(const Ray& ray, Interval t_range) const;
    // Whether any triangle is hit within t_range; stops at the first.
    bool occluded(const Ray& ray, Interval t_range) const;
    // The normal follows the triangle's winding; the shading normal interpolates the vertex
    // normals when there are any (turned to the normal's side); uv interpolates the vertex uvs,
    // or is the barycentric (u, v) without them.
    // uv is always found (it is cheap); its derivatives only when asked for (Uv::compute).
    SurfacePoint surface_at(const Ray& ray, const ShapeHit& hit, Uv uv = Uv::compute) const;
    // The sum of its triangles' areas. Points are drawn on it through its triangles, picked by
    // area from a table that whoever samples it keeps (SurfaceSampler).
    float area() const;
};

// The watertight test (as Triangle's) on the mesh's triangle `index`; two-sided.
std::optional<ShapeHit> intersect_triangle(const MeshData& mesh, std::uint32_t index,
                                           const Ray& ray, Interval t_range);

}  // namespace glint
