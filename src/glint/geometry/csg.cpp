// CSG by walking both operands' crossings along the ray in order and keeping the first that lies
// on the result's surface (the classic inside/outside classification).
#include "glint/geometry/csg.h"

#include <cmath>

#include "glint/geometry/shape.h"
#include "glint/geometry/sphere_tracing.h"

namespace glint {

namespace {

constexpr std::uint64_t kFromB = 1;    // the hit is on operand b (else a)
constexpr std::uint64_t kFlipped = 2;  // its normal is turned around

// One operand's next surface crossing along the ray, and whether the ray is inside the operand
// just before it.
struct Crossing {
    std::optional<ShapeHit> hit;
    bool inside_before = false;
};

// Whether the ray leaves the shape at the hit, where the hit itself says so: the fractals mark
// the hits where rays leave them, since their estimated normals are noisy at the epsilon scale.
// Transforms keep inside and outside; a CSG level turns b of a difference inside out.
std::optional<bool> marked_leaving(const Shape& shape, const ShapeHit& hit) {
    if (std::holds_alternative<JuliaSet>(shape) || std::holds_alternative<Mandelbulb>(shape)) {
        return hit.part == kLeavingHit;
    }
    if (const auto* placed = std::get_if<Transformed>(&shape)) {
        return marked_leaving(*placed->shape, hit);
    }
    if (const auto* moving = std::get_if<Moving>(&shape))
        return marked_leaving(*moving->shape, hit);
    if (const auto* csg = std::get_if<Csg>(&shape)) {
        ShapeHit operand_hit = hit;
        operand_hit.csg_path = hit.csg_path >> 2;
        const auto leaving =
            marked_leaving((hit.csg_path & kFromB) ? *csg->b : *csg->a, operand_hit);
        if (leaving && (hit.csg_path & kFlipped)) return !*leaving;
        return leaving;
    }
    return std::nullopt;
}

bool inside_without_crossing(const Shape& shape, const Ray& ray, float t_min);

// The next crossing at or after t_min. Whether the ray is inside before it follows from the
// direction in which it crosses: leaving through the surface means it was inside.
Crossing next_crossing(const Shape& shape, const Ray& ray, float t_min) {
    Crossing c;
    c.hit = intersect(shape, ray, {t_min, kInfinity});
    if (c.hit) {
        const auto leaving = marked_leaving(shape, *c.hit);
        c.inside_before =
            leaving ? *leaving : dot(surface_at(shape, ray, *c.hit).normal, ray.direction) > 0;
    } else {
        c.inside_before = inside_without_crossing(shape, ray, t_min);
    }
    return c;
}

// Whether the ray is inside the shape from t_min on, where it crosses the shape's surface no
// more. A bounded solid has then been left, or was never entered. The unbounded ones keep a
// side: a half-space the one the ray heads to; a placed shape its shape's, along the ray in its
// space; a CSG shape what its operation makes of its operands' sides there, each found from its
// own next crossing (a CSG shape without crossings may have operands with some).
bool inside_without_crossing(const Shape& shape, const Ray& ray, float t_min) {
    if (const auto* plane = std::get_if<Plane>(&shape)) {
        // Inside when the ray heads inwards (from outside it would cross), whatever rounding
        // says of a start on the plane; when parallel to the plane, inside when it runs below.
        const float along = dot(plane->normal, ray.direction);
        return along != 0 ? along < 0 : dot(plane->normal, ray.at(t_min) - plane->point) < 0;
    }
    // A quadric, or an implicit surface cut open by its box, is the solid f < 0 as far as CSG
    // goes (POV-Ray's infinite cylinder in an intersection): its side is f's sign, halfway along
    // what remains of the ray in its box, away from the crossing just passed.
    const auto side_of = [&](const Bounds3& box, const auto& f) {
        const auto chord = intersect_slabs(box, ray, {t_min, kInfinity});
        const float t = chord && chord->max < kInfinity ? (chord->min + chord->max) / 2 : t_min;
        const Point3 p = ray.at(t);
        return f(p) < 0;
    };
    if (const auto* quadric = std::get_if<Quadric>(&shape)) {
        return side_of(quadric->clip,
                       [&](Point3 p) { return quadric_value(*quadric, p.x, p.y, p.z); });
    }
    if (const auto* surface = std::get_if<ImplicitSurface>(&shape);
        surface && point_cut_open(*surface)) {
        return side_of(surface->region, [&](Point3 p) { return surface->f->value(p); });
    }
    if (glint::bounds(shape).is_finite()) return false;
    if (const auto* placed = std::get_if<Transformed>(&shape)) {
        const ObjectRay o = to_object(placed->world_from_object(), ray);
        return inside_without_crossing(*placed->shape, o.ray, t_min * o.scale);
    }
    if (const auto* moving = std::get_if<Moving>(&shape)) {
        const ObjectRay o = to_object(moving->motion->at(ray.time), ray);
        return inside_without_crossing(*moving->shape, o.ray, t_min * o.scale);
    }
    if (const auto* csg = std::get_if<Csg>(&shape)) {
        const bool in_a = next_crossing(*csg->a, ray, t_min).inside_before;
        const bool in_b = next_crossing(*csg->b, ray, t_min).inside_before;
        switch (csg->operation) {
            case CsgOperation::union_of:
            case CsgOperation::merge:
                return in_a || in_b;
            case CsgOperation::intersection:
            case CsgOperation::clip:
                return in_a && in_b;
            case CsgOperation::difference:
                return in_a && !in_b;
        }
    }
    return false;
}

// Whether a crossing of one operand lies on the result's surface, given whether the ray is
// inside the other operand there; and whether its normal must be turned around.
bool on_result_surface(CsgOperation op, bool on_b, bool inside_other, bool& flipped) {
    flipped = false;
    switch (op) {
        case CsgOperation::union_of:
            return true;
        case CsgOperation::merge:
            return !inside_other;
        case CsgOperation::intersection:
            return inside_other;
        case CsgOperation::difference:
            flipped = on_b;
            return on_b ? inside_other : !inside_other;
        case CsgOperation::clip:
            return !on_b && inside_other;
    }
    return false;
}

// The float after t, so that the walk moves past a crossing and never finds it again.
float after(float t) { return std::nextafter(t, kInfinity); }

}  // namespace

Bounds3 Csg::bounds() const {
    const Bounds3 ba = glint::bounds(*a), bb = glint::bounds(*b);
    switch (operation) {
        case CsgOperation::union_of:
        case CsgOperation::merge:
            return merge(ba, bb);
        case CsgOperation::intersection:
        case CsgOperation::clip:
            return overlap(ba, bb);
        case CsgOperation::difference:
            return ba;
    }
    return ba;
}

std::optional<ShapeHit> Csg::intersect(const Ray& ray, Interval t_range) const {
    Crossing ca = next_crossing(*a, ray, t_range.min);
    Crossing cb = next_crossing(*b, ray, t_range.min);
    // Every crossing toggles inside/outside, so the walk ends after finitely many; the cap
    // only guards against operands that are not closed.
    for (int step = 0; step < 1024; ++step) {
        if (!ca.hit && !cb.hit) return std::nullopt;
        const bool on_b = !ca.hit || (cb.hit && cb.hit->t < ca.hit->t);
        Crossing& c = on_b ? cb : ca;
        const Crossing& other = on_b ? ca : cb;
        const float t = c.hit->t;
        if (t > t_range.max) return std::nullopt;
        bool flipped = false;
        if (on_result_surface(operation, on_b, other.inside_before, flipped)) {
            ShapeHit hit = *c.hit;
            hit.csg_path = (hit.csg_path << 2) | (on_b ? kFromB : 0) | (flipped ? kFlipped : 0);
            return hit;
        }
        const bool inside_after = !c.inside_before;
        const Shape& shape = on_b ? *b : *a;
        c = next_crossing(shape, ray, after(t));
        // Without a further crossing, a bounded solid has been left for good (a ray that only
        // grazed a fractal's shell may have no exit); a half-space keeps the side last crossed to.
        if (!c.hit && !glint::bounds(shape).is_finite()) c.inside_before = inside_after;
    }
    return std::nullopt;
}

std::uint32_t operand_material(const Shape& shape, const ShapeHit& hit) {
    std::uint32_t material = 0;
    std::uint64_t path = hit.csg_path;
    for (const Shape* s = &shape;;) {
        if (const auto* placed = std::get_if<Transformed>(s)) {
            s = placed->shape.get();
        } else if (const auto* moving = std::get_if<Moving>(s)) {
            s = moving->shape.get();
        } else if (const auto* csg = std::get_if<Csg>(s)) {
            const bool on_b = path & kFromB;
            if (const std::uint32_t own = on_b ? csg->material_b : csg->material_a) material = own;
            s = on_b ? csg->b.get() : csg->a.get();
            path >>= 2;
        } else {
            return material;
        }
    }
}

bool has_operand_materials(const Shape& shape) {
    if (const auto* placed = std::get_if<Transformed>(&shape))
        return has_operand_materials(*placed->shape);
    if (const auto* moving = std::get_if<Moving>(&shape))
        return has_operand_materials(*moving->shape);
    if (const auto* csg = std::get_if<Csg>(&shape))
        return csg->material_a || csg->material_b || has_operand_materials(*csg->a) ||
               has_operand_materials(*csg->b);
    return false;
}

SurfacePoint Csg::surface_at(const Ray& ray, const ShapeHit& hit, Uv uv) const {
    const std::uint64_t bits = hit.csg_path & 3;
    ShapeHit operand_hit = hit;
    operand_hit.csg_path = hit.csg_path >> 2;
    SurfacePoint sp = glint::surface_at((bits & kFromB) ? *b : *a, ray, operand_hit, uv);
    if (bits & kFlipped) {
        sp.normal = -sp.normal;
        sp.shading_normal = -sp.shading_normal;
        sp.dndu = -sp.dndu;
        sp.dndv = -sp.dndv;
    }
    return sp;
}

}  // namespace glint
