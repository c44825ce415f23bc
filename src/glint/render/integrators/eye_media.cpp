// Inside or outside each refracting object, asked at every place eye rays may start: the answer
// holds when all places agree, and is warned about when they do not.
#include "glint/render/integrators/eye_media.h"

#include <algorithm>
#include <optional>

#include "glint/geometry/point_inside.h"
#include "glint/math/constants.h"

namespace glint {

namespace {

// Where eye rays start: each corner and the centre of the film, through the centre and the rim
// of the lens, at both ends of the shutter. The centre ray's origin comes first.
std::vector<Point3> eye_ray_origins(const Camera& camera, int width, int height) {
    constexpr float kAlmostOne = 0x1.fffffep-1f;
    const float w = float(width), h = float(height);
    const Point2 films[] = {{w / 2, h / 2}, {0, 0}, {w, 0}, {0, h}, {w, h}};
    std::vector<Point2> lenses = {{0.5f, 0.5f}};
    if (camera.has_lens())
        lenses.insert(lenses.end(), {{0, 0.5f},
                                     {kAlmostOne, 0.5f},
                                     {0.5f, 0},
                                     {0.5f, kAlmostOne},
                                     {0, 0},
                                     {kAlmostOne, 0},
                                     {0, kAlmostOne},
                                     {kAlmostOne, kAlmostOne}});
    std::vector<float> times = {camera.shutter_time(0)};
    if (camera.has_shutter()) times.push_back(camera.shutter_time(kAlmostOne));
    std::vector<Point3> origins;
    for (const float time : times)
        for (const Point2 lens : lenses)
            for (const Point2 film : films) {
                const Point3 o = camera.generate_ray(film, lens, time).origin;
                // A pinhole's rays all start at the eye: each place is asked about once.
                if (std::find(origins.begin(), origins.end(), o) == origins.end())
                    origins.push_back(o);
            }
    return origins;
}

// Whether p is inside the shape: a plane's inside is behind its normal, the side a ray leaves
// it from; other shapes as point_inside says.
std::optional<bool> inside(const Shape& shape, Point3 p) {
    if (const auto* plane = std::get_if<Plane>(&shape))
        return dot(p - plane->point, plane->normal) < 0;
    return point_inside(shape, p);
}

std::string subject(const Shape& shape, std::uint32_t primitive, const Material& m) {
    return "object " + std::to_string(primitive) + " (" + std::string(shape_name(shape)) +
           ", material \"" + m.name + "\")";
}

}  // namespace

EyeMedia find_eye_media(const Camera& camera, int width, int height,
                        std::span<const Primitive> primitives, std::span<const Material> materials,
                        std::span<const std::uint32_t> material_of) {
    EyeMedia media;
    std::vector<Point3> origins;
    for (std::uint32_t i = 0; i < primitives.size(); ++i) {
        const Material& m = materials[material_of[i]];
        if (!(m.transmit > 0)) continue;  // only refracted rays enter media
        const Shape& shape = primitives[i].shape;
        if (origins.empty()) origins = eye_ray_origins(camera, width, height);
        int in = 0, out = 0, unknown = 0;
        bool centre_inside = false;  // where the centre ray, origins.front(), starts
        for (const Point3 p : origins) {
            const std::optional<bool> answer = inside(shape, p);
            if (!answer) {
                unknown += bounds(shape).contains(p);
            } else {
                (*answer ? in : out) += 1;
                if (p == origins.front()) centre_inside = *answer;
            }
        }
        if (unknown > 0) {
            media.warnings.push_back(
                "eye rays start within the bounds of " + subject(shape, i, m) +
                ", which refracts but has no inside to ask about (it is not a closed solid): "
                "they start as if outside it");
            continue;
        }
        if (in > 0 && out > 0)
            media.warnings.push_back(
                "eye rays start both inside and outside " + subject(shape, i, m) +
                " (the lens, the orthographic window or the moving camera crosses its surface): "
                "all of them start " +
                (centre_inside ? "inside" : "outside") + " it, as the centre ray does");
        if (centre_inside) media.primitives.push_back(i);
    }
    // Outermost first: a solid nested in another is the smaller of the two.
    const auto volume = [&](std::uint32_t i) {
        const Bounds3 b = bounds(primitives[i].shape);
        if (!b.is_finite()) return kInfinity;
        const Vector3 d = b.diagonal();
        return d.x * d.y * d.z;
    };
    std::stable_sort(media.primitives.begin(), media.primitives.end(),
                     [&](std::uint32_t a, std::uint32_t b) { return volume(a) > volume(b); });
    return media;
}

}  // namespace glint
