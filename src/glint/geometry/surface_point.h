// What traversal knows about a hit (ShapeHit), and the full surface point built from it.
#pragma once

#include <cstdint>

#include "glint/math/vector.h"

namespace glint {

// The cheap part of a hit: the ray parameter and whatever the intersection routine found on the
// way that surface_at() needs again (barycentrics for triangles, the face for boxes).
struct ShapeHit {
    float t = 0;
    float u = 0, v = 0;
    std::uint32_t part = 0;
    // For hits on CSG shapes: two bits per CSG level, innermost level in the highest bits used,
    // saying which operand was hit and whether its normal is turned around (see csg.h).
    std::uint64_t csg_path = 0;
};

// Whether surface_at() computes SurfacePoint::uv. Most materials never read it, and it costs the
// sphere an arc tangent and an arc cosine at every hit; skipped, uv is (0, 0).
enum class Uv : bool { skip, compute };

// The footprint of a texture lookup: how uv changes from one pixel to the next across (x) and
// down (y) the image, from the ray's differentials (pencil.h). Zero: a lookup at a point.
struct UvFootprint {
    float dudx = 0, dvdx = 0, dudy = 0, dvdy = 0;
};

struct SurfacePoint {
    Point3 p;
    // Unit geometric normal. On closed shapes it points outwards; on open ones (planes,
    // triangles) it is the side the description names. Never flipped towards the ray here.
    Normal3 normal;
    // Unit normal for shading: the geometric one, or one interpolated from vertex normals for
    // smooth shading. On the same side of the surface as `normal`.
    Normal3 shading_normal;
    // Texture coordinates; their range and meaning depend on the shape.
    Point2 uv;
    // How the point and the shading normal change with uv, where the shape computes uv and
    // knows them (has_derivatives): what ray differentials need to carry a pencil of rays across
    // the surface and to find the texture footprint. dndu and dndv are zero on flat faces.
    Vector3 dpdu, dpdv, dndu, dndv;
    bool has_derivatives = false;
    // Set by the integrator when the ray carries differentials; textures filter over it.
    UvFootprint footprint;
    // How far p may lie off the true surface, for shapes found iteratively (implicit surfaces,
    // fractals); 0 for the analytic ones. Secondary rays start at least this far off.
    float error = 0;
};

}  // namespace glint
