// A shape cut into pieces that are easy to draw on uniformly (spheres, rings, parallelograms,
// triangles, tubes), one picked by its area, then a point on it.
#include "glint/geometry/surface_sampler.h"

#include <cmath>

#include "glint/geometry/shape.h"
#include "glint/math/constants.h"

namespace glint {

namespace {

using Sampler = SurfaceSampler;

float area_of(const Sampler::Piece& piece) {
    struct Area {
        float operator()(const Sampler::Sphere& s) const { return 4 * kPi * s.radius * s.radius; }
        float operator()(const Sampler::Annulus& a) const {
            return kPi * (a.outer * a.outer - a.inner * a.inner);
        }
        float operator()(const Sampler::Parallelogram& p) const {
            return length(cross(p.e1, p.e2));
        }
        float operator()(const Sampler::Triangle& t) const {
            return 0.5f * length(cross(t.v1 - t.v0, t.v2 - t.v0));
        }
        float operator()(const Sampler::Tube& t) const {
            return 2 * kPi * t.radius * length(t.axis);
        }
    };
    return std::visit(Area{}, piece);
}

// A point drawn uniformly on the piece, with its normal.
struct Draw {
    Point2 u;

    SurfaceSample operator()(const Sampler::Sphere& s) const {
        const Vector3 d = sample_uniform_sphere(u);
        return {s.center + d * s.radius, Normal3(d)};
    }
    SurfaceSample operator()(const Sampler::Annulus& a) const {
        const float r2 = a.inner * a.inner + u.x * (a.outer * a.outer - a.inner * a.inner);
        const float r = std::sqrt(r2), phi = 2 * kPi * u.y;
        return {a.center + (a.s * std::cos(phi) + a.t * std::sin(phi)) * r, a.normal};
    }
    SurfaceSample operator()(const Sampler::Parallelogram& p) const {
        return {p.corner + p.e1 * u.x + p.e2 * u.y, p.normal};
    }
    SurfaceSample operator()(const Sampler::Triangle& t) const {
        const Point2 b = sample_uniform_triangle(u);
        return {t.v0 + (t.v1 - t.v0) * b.y + (t.v2 - t.v0) * (1 - b.x - b.y), t.normal};
    }
    SurfaceSample operator()(const Sampler::Tube& t) const {
        const float phi = 2 * kPi * u.y;
        const Vector3 out = t.s * std::cos(phi) + t.t * std::sin(phi);
        return {t.base + t.axis * u.x + out * t.radius, Normal3(out)};
    }
};

Sampler::Annulus annulus(Point3 center, Vector3 normal, float inner, float outer) {
    Sampler::Annulus a{center, {}, {}, Normal3(normal), inner, outer};
    orthonormal_basis(normal, a.s, a.t);
    return a;
}

Sampler::Triangle triangle(Point3 v0, Point3 v1, Point3 v2) {
    return {v0, v1, v2, Normal3(normalize(cross(v1 - v0, v2 - v0)))};
}

// Whether the polygon turns the same way at every vertex (collinear runs allowed).
bool is_convex(const Polygon& polygon) {
    const auto& v = polygon.vertices;
    const std::size_t n = v.size();
    bool left = false, right = false;
    for (std::size_t i = 0; i < n; ++i) {
        const float turn = dot(polygon.normal, cross(v[(i + 1) % n] - v[i], v[(i + 2) % n] - v[i]));
        left |= turn > 0;
        right |= turn < 0;
    }
    return !(left && right);
}

// The pieces of a shape in its own space; false when it cannot be drawn on.
struct Pieces {
    std::vector<Sampler::Piece>& out;

    bool operator()(const Sphere& s) const {
        out.push_back(Sampler::Sphere{s.center, s.radius});
        return true;
    }
    bool operator()(const Disk& d) const {
        out.push_back(annulus(d.center, normalize(to_vector(d.normal)), d.inner_radius, d.radius));
        return true;
    }
    bool operator()(const glint::Triangle& t) const {
        out.push_back(triangle(t.vertices[0], t.vertices[1], t.vertices[2]));
        return true;
    }
    bool operator()(const Polygon& p) const {
        if (!is_convex(p)) return false;
        for (std::size_t i = 1; i + 1 < p.vertices.size(); ++i) {
            Sampler::Triangle t = triangle(p.vertices[0], p.vertices[i], p.vertices[i + 1]);
            t.normal = p.normal;
            // Collinear runs of vertices make empty fans, which are never drawn.
            if (area_of(t) > 0) out.push_back(t);
        }
        return true;
    }
    bool operator()(const Box& b) const {
        const Vector3 size = b.max - b.min;
        const Vector3 axes[3] = {{size.x, 0, 0}, {0, size.y, 0}, {0, 0, size.z}};
        for (int axis = 0; axis < 3; ++axis) {
            const Vector3 e1 = axes[(axis + 1) % 3], e2 = axes[(axis + 2) % 3];
            Vector3 n{};
            n = axis == 0 ? Vector3{1, 0, 0} : axis == 1 ? Vector3{0, 1, 0} : Vector3{0, 0, 1};
            out.push_back(Sampler::Parallelogram{b.min, e1, e2, Normal3(-n)});
            out.push_back(Sampler::Parallelogram{b.max - e1 - e2, e1, e2, Normal3(n)});
        }
        return true;
    }
    bool operator()(const Cylinder& c) const {
        const Vector3 axis = c.top - c.base;
        const Vector3 a = normalize(axis);
        Sampler::Tube tube{c.base, axis, {}, {}, c.radius};
        orthonormal_basis(a, tube.s, tube.t);
        out.push_back(tube);
        if (c.capped) {
            out.push_back(annulus(c.base, -a, 0, c.radius));
            out.push_back(annulus(c.top, a, 0, c.radius));
        }
        return true;
    }
    bool operator()(const TriangleMesh& m) const {
        const MeshData& mesh = *m.data;
        for (const auto& tri : mesh.triangles)
            out.push_back(
                triangle(mesh.positions[tri[0]], mesh.positions[tri[1]], mesh.positions[tri[2]]));
        return true;
    }
    bool operator()(const auto&) const { return false; }
};

}  // namespace

std::optional<SurfaceSampler> SurfaceSampler::of(const Shape& shape) {
    SurfaceSampler sampler;
    const Shape* inner = &shape;
    // Transforms nest; their product maps the innermost shape's points.
    while (const auto* t = std::get_if<Transformed>(inner)) {
        sampler.transform_ = sampler.transform_ ? *sampler.transform_ * t->world_from_object()
                                                : t->world_from_object();
        inner = t->shape.get();
    }
    if (!std::visit(Pieces{sampler.pieces_}, *inner) || sampler.pieces_.empty())
        return std::nullopt;
    std::vector<float> areas;
    for (const Piece& piece : sampler.pieces_) areas.push_back(area_of(piece));
    for (const float a : areas) sampler.area_ += a;
    if (!(sampler.area_ > 0) || !std::isfinite(sampler.area_)) return std::nullopt;
    if (sampler.pieces_.size() > 1)
        sampler.by_area_ = std::make_shared<const DiscreteDistribution>(areas);
    return sampler;
}

namespace {

// |det M| of the transform's linear part.
float determinant(const Transform& m) {
    const auto& a = m.matrix().m;
    return a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) -
           a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
           a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
}

}  // namespace

SurfaceSample SurfaceSampler::sample(Point2 u) const {
    std::size_t piece = 0;
    if (by_area_) piece = by_area_->sample(u.x, &u.x);
    SurfaceSample s = std::visit(Draw{u}, pieces_[piece]);
    s.pdf = 1 / area_;
    if (transform_) {
        // Areas scale by |det M| |M^-T n| at a point whose unit normal is n.
        const Transform& m = *transform_;
        const Normal3 n = m(s.normal);  // M^-T n, not normalised
        const float stretch = std::abs(determinant(m)) * length(to_vector(n));
        s.p = m(s.p);
        s.normal = normalize(n);
        s.pdf /= stretch;
    }
    return s;
}

SurfaceSample SurfaceSampler::sample_seen_from(Point3 from, Point2 u) const {
    const auto* sphere = std::get_if<Sphere>(&pieces_.front());
    if (pieces_.size() != 1 || transform_ || !sphere) return sample(u);
    const Vector3 to_center = sphere->center - from;
    const float d2 = length_squared(to_center), r2 = sphere->radius * sphere->radius;
    if (!(d2 > r2 * 1.0001f)) return sample(u);  // on or inside the sphere
    const float d = std::sqrt(d2);
    // 1 - cos_max written so that it keeps its digits when the sphere looks small.
    const float sin2_max = r2 / d2, cos_max = std::sqrt(1 - sin2_max);
    const float one_minus_cos_max = sin2_max / (1 + cos_max);
    const Vector3 w = from_frame(sample_uniform_cone(u, cos_max), to_center / d);
    // The near point along w.
    const float b = dot(w, to_center);
    const float t = b - std::sqrt(std::max(0.0f, r2 - length_squared(to_center - w * b)));
    const Vector3 normal = normalize(from + w * t - sphere->center);
    SurfaceSample s{sphere->center + normal * sphere->radius, Normal3(normal), 0};
    // pdf by solid angle 1 / (2 pi (1 - cos_max)), turned into one by area.
    const float cos_at_point = std::abs(dot(normal, w));
    s.pdf = cos_at_point / (2 * kPi * one_minus_cos_max * t * t);
    return s;
}

float SurfaceSampler::area() const {
    if (!transform_) return area_;
    // 1 / pdf is the area where a transform stretches the object's surface evenly; unevenly
    // (an ellipsoid, whose area has no closed form) its mean over points spread evenly on the
    // object is.
    constexpr int n = 16;
    double sum = 0;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j)
            sum += 1 / double(sample({(float(i) + 0.5f) / n, (float(j) + 0.5f) / n}).pdf);
    return float(sum / (n * n));
}

float SurfaceSampler::pdf_seen_from(Point3 from, Point3 q, Normal3 n) const {
    const auto* sphere = std::get_if<Sphere>(&pieces_.front());
    if (pieces_.size() == 1 && !transform_ && sphere) {
        const Vector3 to_center = sphere->center - from;
        const float d2 = length_squared(to_center), r2 = sphere->radius * sphere->radius;
        if (d2 > r2 * 1.0001f) {
            // As sample_seen_from draws it: uniform over the cone the sphere fills.
            const float sin2_max = r2 / d2, cos_max = std::sqrt(1 - sin2_max);
            const float one_minus_cos_max = sin2_max / (1 + cos_max);
            const Vector3 w = q - from;
            const float t2 = length_squared(w);
            if (!(t2 > 0)) return 0;
            const float cos_at_point =
                std::abs(dot(normalize(q - sphere->center), w)) / std::sqrt(t2);
            return cos_at_point / (2 * kPi * one_minus_cos_max * t2);
        }
    }
    if (!transform_) return 1 / area_;
    // The object's normal there is M^T n up to length, and areas stretch by |det M| |M^-T n_o|
    // for the unit object normal n_o: |det M| / |M^T n|.
    const Normal3 object_normal = transform_->inverse()(n);  // (M^-1)^-T n = M^T n
    const float stretch = std::abs(determinant(*transform_)) / length(to_vector(object_normal));
    return 1 / (area_ * stretch);
}

}  // namespace glint
