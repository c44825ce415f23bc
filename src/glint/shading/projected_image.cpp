// POV-Ray's image_map projections (planar, spherical, cylindrical), with its own angles.
#include "glint/shading/projected_image.h"

#include <algorithm>
#include <cmath>

#include "glint/math/constants.h"

namespace glint {

namespace {

// The angle round y from +x towards +z, over a turn: in [0, 1).
double turn_round_y(double x, double z) {
    double a = std::atan2(z, x) / (2 * kPi);
    if (a < 0) a += 1;
    return a >= 1 ? 0 : a;
}

}  // namespace

std::optional<Point2> projected_uv(ImageProjection projection, bool once, Point3 q) {
    const double x = q.x, y = q.y, z = q.z;
    double u = 0, v = 0;
    switch (projection) {
        case ImageProjection::planar:
            u = x;
            v = y;
            break;
        case ImageProjection::spherical: {
            const double r = std::sqrt(x * x + y * y + z * z);
            if (!(r > 0)) return std::nullopt;
            v = 0.5 + std::asin(std::clamp(y / r, -1.0, 1.0)) / kPi;
            u = x == 0 && z == 0 ? 0 : turn_round_y(x, z);
            break;
        }
        case ImageProjection::cylindrical:
            if (x == 0 && z == 0) return std::nullopt;
            u = turn_round_y(x, z);
            v = y;
            break;
    }
    if (!std::isfinite(u) || !std::isfinite(v)) return std::nullopt;
    if (once && !(u >= 0 && u < 1 && v >= 0 && v < 1)) return std::nullopt;
    return Point2{float(u), float(v)};
}

Color evaluate(const ProjectedImage& texture, Point3 p) {
    const auto uv = projected_uv(texture.projection, texture.once, texture.to_projection(p));
    return uv ? sample(texture.image, *uv) : texture.outside;
}

}  // namespace glint
