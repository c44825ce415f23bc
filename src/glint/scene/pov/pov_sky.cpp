// Baking a sky_sphere: its pigments seen from the centre of the unit sphere, pixel by pixel.
#include "glint/scene/pov/pov_sky.h"

#include <algorithm>
#include <memory>
#include <vector>

#include "glint/math/interval.h"
#include "glint/shading/pattern_texture.h"

namespace glint {

namespace {

PovVector pigment_color(const PovPigment& pigment, Point3 pattern_p);

// A colour map's stop at a point of the map's pattern space: its colour, or its pigment's.
PovVector stop_color(const PovColorStop& stop, Point3 pattern_p) {
    if (!stop.pigment) return stop.color;
    return pigment_color(*stop.pigment, stop.pigment->transform.inverse()(pattern_p));
}

// The pigment's five components (r, g, b, filter, transmit) at a point of its pattern's space:
// a colour, or its pattern through its colour or pigment map.
PovVector pigment_color(const PovPigment& pigment, Point3 pattern_p) {
    if (pigment.kind == PovPigment::Kind::image) {
        // Seen from the sphere's centre, whatever the projection's name.
        const Color c = evaluate(*pigment.image, pattern_p);
        PovVector v = pigment.color;
        v[0] = c.r, v[1] = c.g, v[2] = c.b;
        return v;
    }
    if (pigment.kind != PovPigment::Kind::pattern) return pigment.color;
    const std::vector<PovColorStop>& stops = pigment.map.stops;
    PovVector c = PovVector::of(0, 5);
    if (pigment.average) {
        double weights = 0;
        for (const PovColorStop& stop : stops) {
            const PovVector s = stop_color(stop, pattern_p);
            for (int i = 0; i < 5; ++i) c[i] += stop.at * s[i];
            weights += stop.at;
        }
        for (int i = 0; i < 5; ++i) c[i] = weights != 0 ? c[i] / weights : 0;
        return c;
    }
    const MapSpan span = span_at(stops, pattern_value(pigment.spec, pattern_p));
    const PovVector lower = stop_color(stops[span.lower], pattern_p);
    const PovVector upper = span.weight == 0 ? lower : stop_color(stops[span.upper], pattern_p);
    for (int i = 0; i < 5; ++i) c[i] = lower[i] * (1 - span.weight) + upper[i] * span.weight;
    return c;
}

}  // namespace

SkyImage bake_sky(const PovSkySphere& sky, Color background,
                  const std::function<Color(Color)>& decode, int width) {
    const int height = width / 2;
    auto image = std::make_shared<Image>(width, height);
    const Transform to_sky = sky.transform.inverse();
    const Color emission{float(sky.emission[0]), float(sky.emission[1]), float(sky.emission[2])};
    std::vector<Transform> to_pigment;  // sky space to each pigment's pattern space
    for (const PovPigment& pigment : sky.pigments)
        to_pigment.push_back(pigment.transform.inverse());
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const Point2 uv{(float(x) + 0.5f) / float(width), (float(y) + 0.5f) / float(height)};
            const Vector3 d = sky_image_direction(uv);
            const Point3 p = to_sky(Point3{d.x, d.y, d.z});
            Color c = background;
            for (std::size_t i = 0; i < sky.pigments.size(); ++i) {
                const PovVector v = pigment_color(sky.pigments[i], to_pigment[i](p));
                const Color rgb = decode(Color{float(v[0]), float(v[1]), float(v[2])});
                const float filter = float(v[3]), transmit = float(v[4]);
                c = rgb * std::max(0.0f, 1 - filter - transmit) +
                    c * (rgb * filter + Color::gray(transmit));
            }
            const Color lit = c * emission;
            // A sky image is finite and non-negative (sky.h).
            const auto clean = [](float v) { return v > 0 && v < kInfinity ? v : 0.0f; };
            image->at(x, y) = Color{clean(lit.r), clean(lit.g), clean(lit.b)};
        }
    SkyImage baked;
    baked.image = std::move(image);
    return baked;
}

}  // namespace glint
