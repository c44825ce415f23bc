// Constructive solid geometry on closed solids, with POV-Ray's four operations:
//   union         every surface of both operands, internal ones included;
//   merge         the surface of the union only (no internal surfaces);
//   intersection  the surface of the common part;
//   difference    a minus b: a's surface outside b, and b's inside a, turned inside out;
// and POV-Ray's clipped_by:
//   clip          a's surface inside b, and nothing of b's: a cut open where b ends.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>

#include "glint/geometry/surface_point.h"
#include "glint/math/bounds.h"
#include "glint/math/interval.h"
#include "glint/math/ray.h"

namespace glint {

struct Shape;

enum class CsgOperation { union_of, merge, intersection, difference, clip };

// Operands must be closed solids (or half-spaces: planes), so that a ray alternately enters and
// leaves them; they may be CSG shapes themselves up to kMaxCsgDepth levels. A clip's a may be
// any surface: only b's inside counts.
struct Csg {
    CsgOperation operation = CsgOperation::union_of;
    std::shared_ptr<const Shape> a, b;  // never null
    // What each operand's surface is painted with, where it has its own (POV-Ray paints each
    // operand's part with its texture): a scene material's index + 1; 0 for the CSG's own.
    std::uint32_t material_a = 0, material_b = 0;

    Bounds3 bounds() const;
    // Walks both operands' hits along the ray in order, tracking whether the ray is inside
    // each, and returns the first hit that lies on the result's surface.
    std::optional<ShapeHit> intersect(const Ray& ray, Interval t_range) const;
    // The operand's surface point, with the normal turned around where the operation turns
    // the operand inside out (b in a difference), so that normals always point out of the result.
    SurfacePoint surface_at(const Ray& ray, const ShapeHit& hit, Uv uv = Uv::compute) const;
};

// The material (index + 1) of the operand the hit lies on, the innermost that has one, through
// transforms and nested CSG; 0 when none has one (the object's own material).
std::uint32_t operand_material(const Shape& shape, const ShapeHit& hit);
// Whether any CSG in the shape paints an operand with its own material.
bool has_operand_materials(const Shape& shape);

// Each level takes two bits of ShapeHit::csg_path, and intersect() and surface_at() recurse once
// a level: the cap keeps both bounded (loaders refuse deeper nesting, DESIGN principle 4).
inline constexpr int kMaxCsgDepth = 32;

}  // namespace glint
