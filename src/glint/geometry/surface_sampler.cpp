// The shapes' own sample(u) under the transforms around them, and a mesh's triangles picked by
// area.
#include "glint/geometry/surface_sampler.h"

#include <cmath>
#include <vector>

#include "glint/geometry/shape.h"

namespace glint {

namespace {

Triangle mesh_triangle(const MeshData& mesh, std::size_t index) {
    const auto& tri = mesh.triangles[index];
    return {{mesh.positions[tri[0]], mesh.positions[tri[1]], mesh.positions[tri[2]]}};
}

// |det M| of the transform's linear part.
float determinant(const Transform& m) {
    const auto& a = m.matrix().m;
    return a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) -
           a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
           a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
}

}  // namespace

std::optional<SurfaceSampler> SurfaceSampler::of(const Shape& shape) {
    const Shape* inner = &shape;
    std::optional<Transform> transform;
    // Transforms nest; their product maps the innermost shape's points.
    while (const auto* t = std::get_if<Transformed>(inner)) {
        transform = transform ? *transform * t->world_from_object() : t->world_from_object();
        inner = t->shape.get();
    }
    std::optional<SurfaceSampler> sampler = std::visit(
        [](const auto& s) -> std::optional<SurfaceSampler> {
            if constexpr (std::is_constructible_v<Drawable, decltype(s)>) {
                if constexpr (std::is_same_v<std::decay_t<decltype(s)>, Polygon>)
                    if (!is_convex(s)) return std::nullopt;
                return SurfaceSampler(s, s.area());
            } else {
                return std::nullopt;
            }
        },
        static_cast<const Shape::variant&>(*inner));
    if (!sampler || !(sampler->area_ > 0) || !std::isfinite(sampler->area_)) return std::nullopt;
    if (const auto* mesh = std::get_if<TriangleMesh>(&sampler->shape_)) {
        std::vector<float> areas;
        for (std::size_t i = 0; i < mesh->data->triangles.size(); ++i)
            areas.push_back(mesh_triangle(*mesh->data, i).area());
        sampler->triangles_by_area_ = std::make_shared<const DiscreteDistribution>(areas);
    }
    sampler->transform_ = transform;
    return sampler;
}

SurfaceSample SurfaceSampler::draw(Point2 u) const {
    if (const auto* mesh = std::get_if<TriangleMesh>(&shape_)) {
        const std::size_t index = triangles_by_area_->sample(u.x, &u.x);
        SurfaceSample s = mesh_triangle(*mesh->data, index).sample(u);
        s.pdf = 1 / area_;
        return s;
    }
    return std::visit(
        [u](const auto& s) {
            if constexpr (requires { s.sample(u); })
                return s.sample(u);
            else
                return SurfaceSample{};
        },
        shape_);
}

SurfaceSample SurfaceSampler::sample(Point2 u) const {
    SurfaceSample s = draw(u);
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
    const auto* sphere = std::get_if<Sphere>(&shape_);
    if (transform_ || !sphere) return sample(u);
    return sphere->sample_seen_from(from, u);
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
    if (!transform_) {
        if (const auto* sphere = std::get_if<Sphere>(&shape_))
            return sphere->pdf_seen_from(from, q);
        return 1 / area_;
    }
    // The object's normal there is M^T n up to length, and areas stretch by |det M| |M^-T n_o|
    // for the unit object normal n_o: |det M| / |M^T n|.
    const Normal3 object_normal = transform_->inverse()(n);  // (M^-1)^-T n = M^T n
    const float stretch = std::abs(determinant(*transform_)) / length(to_vector(object_normal));
    return 1 / (area_ * stretch);
}

}  // namespace glint
