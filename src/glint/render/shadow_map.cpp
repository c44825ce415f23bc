// Rendering the depth maps by casting a ray through each texel's centre, and looking them up
// with percentage-closer filtering, widened to the penumbra for a light with an extent.
#include "glint/render/shadow_map.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>

#include "glint/accel/primitive.h"
#include "glint/math/ray.h"

namespace glint {

namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();

// A cube face is the plane s e_a + u e_b + v e_c for u, v in [-1, 1], with a = face / 2,
// s = +1 for even faces, -1 for odd, b = a + 1 and c = a + 2 (mod 3).
Vector3 axis_vector(int axis, float value) {
    return axis == 0   ? Vector3{value, 0, 0}
           : axis == 1 ? Vector3{0, value, 0}
                       : Vector3{0, 0, value};
}

Vector3 face_direction(int face, float u, float v) {
    const int a = face / 2;
    const float s = face % 2 == 0 ? 1.0f : -1.0f;
    return axis_vector(a, s) + axis_vector((a + 1) % 3, u) + axis_vector((a + 2) % 3, v);
}

// The face a direction leaves the cube by, and its (u, v) there.
int face_of(Vector3 d, float& u, float& v) {
    const float ax = std::abs(d.x), ay = std::abs(d.y), az = std::abs(d.z);
    const int a = ax >= ay && ax >= az ? 0 : ay >= az ? 1 : 2;
    const float major = d[a];
    const float m = std::abs(major);
    u = d[(a + 1) % 3] / m;
    v = d[(a + 2) % 3] / m;
    return 2 * a + (major >= 0 ? 0 : 1);
}

// The ray's distance to the nearest primitive that casts shadows; infinite when none.
float nearest(const Aggregate& aggregate, const Ray& ray) {
    const auto hit = aggregate.intersect(ray, {0, kInf}, kVisibleToShadowRays);
    return hit ? hit->shape_hit.t : kInf;
}

// Tap k of n on the golden-angle spiral over the unit disk (Vogel 1979), turned by `turn`.
Point2 spiral_tap(int k, int n, float turn) {
    const float r = std::sqrt((float(k) + 0.5f) / float(n));
    const float phi = float(k) * 2.39996323f + turn;
    return {r * std::cos(phi), r * std::sin(phi)};
}

// An angle from the bits of p: a wide filter's taps turn from point to point, so that the
// samples of a pixel average their error into noise instead of lining it up into bands.
float turn_at(Point3 p) {
    std::uint32_t h = 2166136261u;
    for (const float c : {p.x, p.y, p.z}) {
        std::uint32_t bits;
        std::memcpy(&bits, &c, sizeof bits);
        h = (h ^ bits) * 16777619u;
    }
    h ^= h >> 15;
    return float(h) * (6.2831853f / 4294967296.0f);
}

}  // namespace

ShadowMap ShadowMap::cube(Point3 light, float light_radius, const Aggregate& aggregate,
                          const ShadowMapSettings& settings, float time) {
    ShadowMap map;
    map.origin_ = light;
    map.light_radius_ = light_radius;
    map.resolution_ = settings.resolution;
    map.settings_ = settings;
    const int r = settings.resolution;
    map.depth_.assign(std::size_t(6) * r * r, kInf);
    tbb::parallel_for(0, 6 * r, [&](int row) {
        const int face = row / r, j = row % r;
        for (int i = 0; i < r; ++i) {
            const float u = (float(i) + 0.5f) * 2 / float(r) - 1;
            const float v = (float(j) + 0.5f) * 2 / float(r) - 1;
            // Stored along the face's axis: the distance along w = face_direction, whose
            // component on the axis is 1, so that a lookup compares without a square root.
            const Vector3 w = face_direction(face, u, v);
            const float length_w = length(w);
            map.depth_[(std::size_t(face) * r + j) * r + i] =
                nearest(aggregate, Ray{light, w / length_w, time}) / length_w;
        }
    });
    return map;
}

ShadowMap ShadowMap::parallel(Vector3 direction, const Bounds3& bounds, const Aggregate& aggregate,
                              const ShadowMapSettings& settings, float time) {
    ShadowMap map;
    map.parallel_ = true;
    map.resolution_ = settings.resolution;
    map.settings_ = settings;
    map.axis_ = direction;
    orthonormal_basis(direction, map.s_, map.t_);
    const Point3 center = bounds.min + bounds.diagonal() / 2;
    map.half_extent_ = std::max(length(bounds.diagonal()) / 2, 1e-6f) * 1.01f;
    map.origin_ = center - direction * map.half_extent_;
    const int r = settings.resolution;
    map.depth_.assign(std::size_t(r) * r, kInf);
    tbb::parallel_for(0, r, [&](int j) {
        for (int i = 0; i < r; ++i) {
            const float a = ((float(i) + 0.5f) * 2 / float(r) - 1) * map.half_extent_;
            const float b = ((float(j) + 0.5f) * 2 / float(r) - 1) * map.half_extent_;
            const Ray ray{map.origin_ + map.s_ * a + map.t_ * b, direction, time};
            map.depth_[std::size_t(j) * r + i] = nearest(aggregate, ray);
        }
    });
    return map;
}

ShadowMap::Projection ShadowMap::project(Point3 q) const {
    const float r = float(resolution_);
    if (parallel_) {
        const Vector3 d = q - origin_;
        const float a = dot(d, s_) / half_extent_, b = dot(d, t_) / half_extent_;
        return {0, (a + 1) / 2 * r, (b + 1) / 2 * r, dot(d, axis_)};
    }
    const Vector3 d = q - origin_;
    float u, v;
    const int face = face_of(d, u, v);
    return {face, (u + 1) / 2 * r, (v + 1) / 2 * r, std::abs(d[face / 2])};
}

std::optional<ShadowMap::Texel> ShadowMap::texel_at(int face, float x, float y) const {
    const int i = int(std::floor(x)), j = int(std::floor(y));
    if (i >= 0 && i < resolution_ && j >= 0 && j < resolution_) return Texel{face, i, j};
    if (parallel_) return std::nullopt;
    // Beyond the face's edge: the texel centre's direction, found on its own face.
    const float r = float(resolution_);
    const float u = (float(i) + 0.5f) * 2 / r - 1, v = (float(j) + 0.5f) * 2 / r - 1;
    float fu, fv;
    const int other = face_of(face_direction(face, u, v), fu, fv);
    const auto clamp = [&](float c) {
        return std::clamp(int(std::floor((c + 1) / 2 * r)), 0, resolution_ - 1);
    };
    return Texel{other, clamp(fu), clamp(fv)};
}

float ShadowMap::texel_size(float distance) const {
    if (parallel_) return 2 * half_extent_ / float(resolution_);
    return distance * 2 / float(resolution_);
}

bool ShadowMap::blocks(const Texel& t, const Receiver& r) const {
    const float d = depth(t);
    if (!std::isfinite(d)) return false;
    const float u = (float(t.i) + 0.5f) * 2 / float(resolution_) - 1;
    const float v = (float(t.j) + 0.5f) * 2 / float(resolution_) - 1;
    // The texel's ray from + lambda along, with lambda the depth's measure, and where it meets
    // the receiver's plane.
    Point3 from = origin_;
    Vector3 along = axis_;
    if (parallel_)
        from = origin_ + s_ * (u * half_extent_) + t_ * (v * half_extent_);
    else
        along = face_direction(t.face, u, v);
    const float facing = dot(r.n, along);
    // A texel whose ray runs along the plane or away from it cannot shadow it.
    if (!(facing < 0)) return false;
    // Depths are measured in steps of `along`, which is longer than a unit off a face's
    // centre (up to sqrt(3) at its corners): the bias, a distance, in the same steps.
    return d + r.bias / length(along) < dot(r.n, r.q - from) / facing;
}

float ShadowMap::lit_share(int face, float x, float y, const Receiver& r) const {
    // The four texel centres round (x, y), weighed by how near each is.
    const float fx = x - 0.5f, fy = y - 0.5f;
    const float x0 = std::floor(fx), y0 = std::floor(fy);
    const float wx = fx - x0, wy = fy - y0;
    float lit = 0, covered = 0;
    for (int k = 0; k < 4; ++k) {
        const float w = (k % 2 ? wx : 1 - wx) * (k / 2 ? wy : 1 - wy);
        if (w == 0) continue;
        const auto texel = texel_at(face, x0 + float(k % 2) + 0.5f, y0 + float(k / 2) + 0.5f);
        if (!texel) continue;
        covered += w;
        if (!blocks(*texel, r)) lit += w;
    }
    return covered > 0 ? lit / covered : 1;
}

std::optional<float> ShadowMap::visibility(Point3 p, Normal3 n) const {
    const float r0 = parallel_ ? dot(p - origin_, axis_) : distance(p, origin_);
    const float size = texel_size(std::max(r0, 0.0f));
    // Moved off the surface along its normal, so that a surface does not shadow itself between
    // texel centres (acne).
    const Receiver receiver{p + to_vector(n) * (size * settings_.bias), to_vector(n),
                            size * settings_.bias};
    const Projection at = project(receiver.q);
    // At the light itself there is no direction to look up; beyond an orthographic map's edge
    // no texel: a feeler answers.
    if (!(at.distance > 0) || !std::isfinite(at.x) || !std::isfinite(at.y)) return std::nullopt;
    if (parallel_ &&
        !(at.x >= 0 && at.x < float(resolution_) && at.y >= 0 && at.y < float(resolution_)))
        return std::nullopt;
    // The filter's half-width in texels: the filter's, or for a light with an extent the
    // penumbra its blockers imply.
    float half = float(settings_.filter - 1) / 2;
    constexpr int kSpiral = 16;  // taps of a filter wider than the grid's
    const float turn = turn_at(p);
    if (light_radius_ > 0) {
        // Blockers: the texels round q, within the cone towards the light's disk as far as a
        // third of the way to it, that are nearer than q's plane.
        const float angle = 2 / float(resolution_);
        const float search = std::clamp(3 * light_radius_ / (at.distance * angle), 1.0f, 24.0f);
        float blockers = 0;
        int found = 0;
        for (int k = 0; k < kSpiral; ++k) {
            const Point2 o = spiral_tap(k, kSpiral, turn);
            const auto texel = texel_at(at.face, at.x + o.x * search, at.y + o.y * search);
            if (!texel || !blocks(*texel, receiver)) continue;
            blockers += depth(*texel);
            ++found;
        }
        if (found == 0) return 1.0f;
        const float z = blockers / float(found);
        // Similar triangles: the penumbra's width at the receiver, as an angle from the light.
        const float penumbra =
            light_radius_ * std::max(at.distance - z, 0.0f) / std::max(z, 1e-20f);
        half = std::max(half, penumbra / (at.distance * angle));
    }
    if (half <= 0) return lit_share(at.face, at.x, at.y, receiver);
    // A filter of up to 7 texels: a grid of taps a texel apart, each bilinear; wider, the
    // spiral's taps over its disk.
    float sum = 0;
    if (half <= 3) {
        // The bilinear taps a texel apart share their texels: each texel of the block they
        // cover is tested once, weighed by the taps that reach it (1 inside, the bilinear
        // weight along the block's first and last rows and columns).
        const int reach = int(std::ceil(half));
        const float fx = at.x - 0.5f, fy = at.y - 0.5f;
        const float x0 = std::floor(fx), y0 = std::floor(fy);
        const float wx = fx - x0, wy = fy - y0;
        for (int b = -reach; b <= reach + 1; ++b) {
            const float row = b == -reach ? 1 - wy : b == reach + 1 ? wy : 1;
            if (row == 0) continue;
            for (int a = -reach; a <= reach + 1; ++a) {
                const float column = a == -reach ? 1 - wx : a == reach + 1 ? wx : 1;
                if (column == 0) continue;
                const auto texel = texel_at(at.face, x0 + float(a) + 0.5f, y0 + float(b) + 0.5f);
                if (!texel || !blocks(*texel, receiver)) sum += row * column;
            }
        }
        return sum / float((2 * reach + 1) * (2 * reach + 1));
    }
    for (int k = 0; k < kSpiral; ++k) {
        const Point2 o = spiral_tap(k, kSpiral, turn);
        sum += lit_share(at.face, at.x + o.x * half, at.y + o.y * half, receiver);
    }
    return sum / float(kSpiral);
}

float ShadowMap::depth_towards(Vector3 d) const {
    float u, v;
    const int face = face_of(d, u, v);
    const float r = float(resolution_);
    const int i = std::clamp(int(std::floor((u + 1) / 2 * r)), 0, resolution_ - 1);
    const int j = std::clamp(int(std::floor((v + 1) / 2 * r)), 0, resolution_ - 1);
    return depth(Texel{face, i, j});
}

}  // namespace glint
