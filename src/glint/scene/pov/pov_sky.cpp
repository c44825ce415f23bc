// Baking a sky_sphere: its pigments seen from the centre of the unit sphere, pixel by pixel.
#include "glint/scene/pov/pov_sky.h"

#include <algorithm>
#include <memory>
#include <vector>

#include "glint/math/interval.h"
#include "glint/shading/pattern_texture.h"

namespace glint {

namespace {

// A pigment with the transforms into its pigment_map entries' spaces inverted once, not at
// every pixel.
struct Prepared {
    const PovPigment* pigment = nullptr;
    // Per stop of its map: into the stop's pigment's space, and that pigment prepared (unset
    // for a colour).
    std::vector<Transform> to_stop;
    std::vector<Prepared> stops;
};

Prepared prepared(const PovPigment& pigment) {
    Prepared p{&pigment, {}, {}};
    for (const PovColorStop& stop : pigment.map.stops) {
        p.to_stop.push_back(stop.pigment ? stop.pigment->transform.inverse() : Transform{});
        p.stops.push_back(stop.pigment ? prepared(*stop.pigment) : Prepared{});
    }
    return p;
}

PovVector pigment_color(const Prepared& prepared, Point3 pattern_p,
                        const std::function<Color(Color)>& encode_image);

// Stop i of a colour map at a point of the map's pattern space: its colour, or its pigment's.
PovVector stop_color(const Prepared& map, std::size_t i, Point3 pattern_p,
                     const std::function<Color(Color)>& encode_image) {
    const PovColorStop& stop = map.pigment->map.stops[i];
    if (!stop.pigment) return stop.color;
    return pigment_color(map.stops[i], map.to_stop[i](pattern_p), encode_image);
}

// The pigment's five components (r, g, b, filter, transmit) at a point of its pattern's space:
// a colour, or its pattern through its colour or pigment map.
PovVector pigment_color(const Prepared& prepared, Point3 pattern_p,
                        const std::function<Color(Color)>& encode_image) {
    const PovPigment& pigment = *prepared.pigment;
    if (pigment.kind == PovPigment::Kind::image) {
        // Seen from the sphere's centre, whatever the projection's name.
        const Color c = encode_image(evaluate(*pigment.image, pattern_p));
        PovVector v = pigment.color;
        v[0] = c.r, v[1] = c.g, v[2] = c.b;
        return v;
    }
    if (pigment.kind != PovPigment::Kind::pattern) return pigment.color;
    const std::vector<PovColorStop>& stops = pigment.map.stops;
    PovVector c = PovVector::of(0, 5);
    if (pigment.average) {
        double weights = 0;
        for (std::size_t s = 0; s < stops.size(); ++s) {
            const PovVector v = stop_color(prepared, s, pattern_p, encode_image);
            for (int i = 0; i < 5; ++i) c[i] += stops[s].at * v[i];
            weights += stops[s].at;
        }
        for (int i = 0; i < 5; ++i) c[i] = weights != 0 ? c[i] / weights : 0;
        return c;
    }
    const MapSpan span = span_at(stops, pattern_value(pigment.spec, pattern_p));
    const PovVector lower = stop_color(prepared, span.lower, pattern_p, encode_image);
    const PovVector upper =
        span.weight == 0 ? lower : stop_color(prepared, span.upper, pattern_p, encode_image);
    for (int i = 0; i < 5; ++i) c[i] = lower[i] * (1 - span.weight) + upper[i] * span.weight;
    return c;
}

}  // namespace

SkyImage bake_sky(const PovSkySphere& sky, Color background,
                  const std::function<Color(Color)>& encode_image, int width) {
    const int height = width / 2;
    auto image = std::make_shared<Image>(width, height);
    const Transform to_sky = sky.transform.inverse();
    const Color emission{float(sky.emission[0]), float(sky.emission[1]), float(sky.emission[2])};
    std::vector<Transform> to_pigment;  // sky space to each pigment's pattern space
    std::vector<Prepared> pigments;
    for (const PovPigment& pigment : sky.pigments) {
        to_pigment.push_back(pigment.transform.inverse());
        pigments.push_back(prepared(pigment));
    }
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const Point2 uv{(float(x) + 0.5f) / float(width), (float(y) + 0.5f) / float(height)};
            const Vector3 d = sky_image_direction(uv);
            const Point3 p = to_sky(Point3{d.x, d.y, d.z});
            Color c = background;
            for (std::size_t i = 0; i < sky.pigments.size(); ++i) {
                const PovVector v = pigment_color(pigments[i], to_pigment[i](p), encode_image);
                const Color rgb{float(v[0]), float(v[1]), float(v[2])};
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
