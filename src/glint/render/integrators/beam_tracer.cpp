// The beam tree of each tile, traced depth first and drawn as it grows: every fragment adds its
// shaded area to the pixels it covers, weighted by the kr and kt products above it.
#include "glint/render/integrators/beam_tracer.h"

#include <algorithm>
#include <cmath>

#include "glint/render/beam/pixel_coverage.h"
#include "glint/render/integrators/surface_context.h"
#include "glint/shading/phong.h"

namespace glint {

using namespace beam;

// A beam: the region of the image it covers, and how it sees the world. to_eye maps the world
// into the space the camera sees through the beam's mirrors and refracting planes (the
// identity for the eye beam); `eye` is the camera's eye mapped back, the beam's virtual eye.
struct BeamIntegrator::Beam {
    Affine to_eye, from_eye;
    Vector3d eye;
    bool bounded = false;  // only what lies beyond `beyond` (its positive side) is seen
    PlaneD beyond;
    Paths region;
    float weight = 1;
    int depth = 1;
    RayKind kind = RayKind::primary;
};

// What the drawing of one tile accumulates: each pixel's colour, and the coverage grids of the
// fragment being drawn and of its lit parts, light by light.
struct BeamIntegrator::TileDrawing {
    Tile tile;
    std::vector<Color> sums;
    CoverageGrid fragment;
    std::vector<CoverageGrid> lit;
    // For the fragment being drawn, light by light: -1 the light reaches all of it, 0 none of
    // it, 1 a part, whose area in each pixel lit[] holds.
    std::vector<float> lit_share;
    Color& sum(int x, int y) {
        return sums[std::size_t(y - tile.y0) * std::size_t(tile.x1 - tile.x0) +
                    std::size_t(x - tile.x0)];
    }
};

BeamIntegrator::Shared BeamIntegrator::prepare(const World& world) {
    auto p = std::make_shared<Polygons>();
    // Integer plane coordinates of 2^-29 of the scene's radius, tolerance 2^-20 of it: room
    // below 2^62 (Clipper's range) for shadows projected far out across a plane.
    const double radius = double(world.scene_radius()) + 1e-30;
    p->scale = std::ldexp(1.0, 29) / radius;
    p->tolerance = std::ldexp(radius, -20);
    p->polygons = beam_polygons(world, p->scale);
    p->bsp = PolygonBsp(p->polygons, p->tolerance);
    p->reach = light_reach(world.lights(), p->polygons, p->tolerance);
    return p;
}

void BeamIntegrator::draw_tile(const Tile& tile, FilmTile& film, RayStats& stats) {
    const std::size_t lights = world_.lights().size();
    TileDrawing drawing{
        tile, std::vector<Color>(std::size_t(tile.x1 - tile.x0) * std::size_t(tile.y1 - tile.y0)),
        CoverageGrid(tile.x0, tile.y0, tile.x1, tile.y1),
        std::vector<CoverageGrid>(lights, CoverageGrid(tile.x0, tile.y0, tile.x1, tile.y1)),
        std::vector<float>(lights)};
    Beam eye;
    eye.eye = Vector3d(world_.camera().pinhole().eye);
    const auto at = [](int x, int y) {
        return IntPoint{ClipperLib::cInt(x) * ClipperLib::cInt(kSubpixel),
                        ClipperLib::cInt(y) * ClipperLib::cInt(kSubpixel)};
    };
    eye.region = {
        {at(tile.x0, tile.y0), at(tile.x1, tile.y0), at(tile.x1, tile.y1), at(tile.x0, tile.y1)}};
    std::vector<Beam> beams{eye};
    while (!beams.empty()) {
        const Beam beam = std::move(beams.back());
        beams.pop_back();
        stats.count(beam.kind);
        trace_beam(beam, drawing, beams, stats);
    }
    // Each pixel's exact average, as one sample at its centre: the scene's filter, a box of one
    // pixel unless it names another, then spreads it as any sample.
    for (int y = tile.y0; y < tile.y1; ++y)
        for (int x = tile.x0; x < tile.x1; ++x)
            film.add_sample({float(x) + 0.5f, float(y) + 0.5f}, drawing.sum(x, y));
}

void BeamIntegrator::trace_beam(const Beam& beam, TileDrawing& drawing, std::vector<Beam>& beams,
                                RayStats& stats) const {
    const RenderSettings& settings = world_.settings();
    const std::vector<PlaneD> bounds = bounds_of_beam(beam);
    Paths rest = beam.region;
    polygons_.bsp.front_to_back(beam.eye, bounds, [&](const BspPiece& piece) {
        const BeamPolygon& polygon = polygons_.polygons[piece.polygon];
        if (!polygon.seen) return true;
        const Paths part = clipped(polygon.frame, piece.region, bounds);
        if (part.empty()) return true;
        const Paths image = projected(polygon.frame, part, beam);
        const Paths fragment = intersection(rest, image);
        if (fragment.empty()) return true;
        rest = difference(rest, image);
        if (beam.depth == 1) ++stats.primary_hits;
        draw_fragment(fragment, polygon, piece.polygon, beam, bounds, drawing);

        // The fragment's reflected and transmitted beams.
        const Material& m = world_.material_of(polygon.primitive);
        if (beam.depth >= settings.max_depth) return !rest.empty();
        const bool eye_outside = polygon.plane.at(beam.eye) > 0;
        if (m.reflect > 0 && beam.weight * m.reflect >= settings.min_weight) {
            const Affine mirror = mirror_in(polygon.plane);
            beams.push_back({beam.to_eye.after(mirror), mirror.after(beam.from_eye),
                             mirror.apply(beam.eye), true,
                             eye_outside ? polygon.plane : polygon.plane.flipped(), fragment,
                             beam.weight * m.reflect, beam.depth + 1, RayKind::reflected});
        }
        if (m.transmit > 0 && beam.weight * m.transmit >= settings.min_weight) {
            // Into the object through its outward normal's side, or out of it: the depth
            // beyond appears scaled by n1 / n2.
            const double eta = eye_outside ? 1 / double(m.ior) : double(m.ior);
            const PlaneD far = eye_outside ? polygon.plane.flipped() : polygon.plane;
            const Affine seen = scale_across(far, eta), back = scale_across(far, 1 / eta);
            beams.push_back({beam.to_eye.after(seen), back.after(beam.from_eye),
                             back.apply(beam.eye), true, far, fragment, beam.weight * m.transmit,
                             beam.depth + 1, RayKind::refracted});
        }
        return !rest.empty();
    });
    if (!rest.empty()) draw_sky(rest, beam, drawing);
}

std::vector<PlaneD> BeamIntegrator::bounds_of_beam(const Beam& beam) const {
    const double tolerance = polygons_.tolerance;
    std::vector<PlaneD> bounds;
    // Strictly beyond the mirror or refracting plane: never the plane's own polygons.
    if (beam.bounded) bounds.push_back({beam.beyond.n, beam.beyond.d + tolerance});
    // The pyramid from the camera's eye through the region's bounding box, a pixel wider, and
    // in front of the eye, mapped back into the world: it keeps projected coordinates finite
    // and small.
    const Camera::Pinhole view = world_.camera().pinhole();
    const RenderSettings& settings = world_.settings();
    const ClipperLib::IntRect box = bounds_of(beam.region);
    const double w = settings.width, h = settings.height;
    const auto kx = [&](double x) { return (2 * x / w - 1) * double(view.half_width); };
    const auto ky = [&](double y) { return (1 - 2 * y / h) * double(view.half_height); };
    const double x0 = double(box.left) / kSubpixel - 1, x1 = double(box.right) / kSubpixel + 1;
    const double y0 = double(box.top) / kSubpixel - 1, y1 = double(box.bottom) / kSubpixel + 1;
    const Vector3d u(view.u), v(view.v), n(view.n), e(view.eye);
    const Vector3d normals[5] = {u - n * kx(x0), n * kx(x1) - u, n * ky(y0) - v, v - n * ky(y1), n};
    for (int i = 0; i < 5; ++i) {
        const double offset = i == 4 ? tolerance : 0;
        bounds.push_back(beam.to_eye.pull_back({normals[i], dot(normals[i], e) + offset}));
    }
    return bounds;
}

Paths BeamIntegrator::clipped(const PlaneFrame& frame, Paths region,
                              std::span<const PlaneD> bounds) {
    for (const PlaneD& plane : bounds) {
        region = clip_to_halfspace(frame, region, plane);
        if (region.empty()) break;
    }
    return region;
}

Paths BeamIntegrator::projected(const PlaneFrame& frame, const Paths& region,
                                const Beam& beam) const {
    const Camera::Pinhole view = world_.camera().pinhole();
    const RenderSettings& settings = world_.settings();
    const Vector3d u(view.u), v(view.v), n(view.n), e(view.eye);
    const double half_w = double(settings.width) / 2, half_h = double(settings.height) / 2;
    Paths image;
    image.reserve(region.size());
    for (const Path& ring : region) {
        Path out;
        out.reserve(ring.size());
        for (const IntPoint& p : ring) {
            const Vector3d d = beam.to_eye.apply(frame.world(p)) - e;
            const double depth = dot(d, n);
            const double x = (dot(d, u) / depth / double(view.half_width) + 1) * half_w;
            const double y = (1 - dot(d, v) / depth / double(view.half_height)) * half_h;
            out.push_back({ClipperLib::cInt(std::llround(x * kSubpixel)),
                           ClipperLib::cInt(std::llround(y * kSubpixel))});
        }
        image.push_back(std::move(out));
    }
    return image;
}

void BeamIntegrator::draw_fragment(const Paths& fragment, const BeamPolygon& polygon,
                                   std::uint32_t polygon_index, const Beam& beam,
                                   std::span<const PlaneD> bounds, TileDrawing& drawing) const {
    const auto lights = world_.lights();
    // The share of each pixel's part of the fragment that each light reaches.
    for (std::size_t l = 0; l < lights.size(); ++l) {
        const LightReach& reach = polygons_.reach[l][polygon_index];
        drawing.lit_share[l] = reach.everywhere ? -1.0f : 0.0f;
        if (reach.everywhere || reach.lit.empty()) continue;
        const Paths lit = clipped(polygon.frame, reach.lit, bounds);
        if (lit.empty()) continue;
        drawing.lit_share[l] = 1;
        drawing.lit[l].add(intersection(fragment, projected(polygon.frame, lit, beam)));
    }
    drawing.fragment.add(fragment);

    const Camera& camera = world_.camera();
    const float radius = world_.scene_radius();
    drawing.fragment.drain([&](int x, int y, double area, double cx, double cy) {
        // The point of the polygon's plane seen at the centroid, and the ray it is seen along
        // (from just before it, for precision: the virtual eye may be far).
        const Vector3d w =
            beam.from_eye.linear(Vector3d(camera.generate_ray({float(cx), float(cy)}).direction));
        const double facing = dot(polygon.plane.n, w);
        if (facing == 0) return;
        const double t = -polygon.plane.at(beam.eye) / facing;
        const Vector3d q = beam.eye + w * t;
        const double length = std::sqrt(dot(w, w));
        const Vector3d unit = w * (1 / length);
        const double back = 1e-4 * double(radius);
        Ray ray;
        ray.origin = Point3(float(q.x - unit.x * back), float(q.y - unit.y * back),
                            float(q.z - unit.z * back));
        ray.direction = unit.to_float();
        ray.time = camera.shutter_open();
        Hit hit{ShapeHit{float(back), 0, 0, polygon.part}, polygon.primitive};
        if (polygon.barycentric) {
            const auto& [a, b, c] = polygon.corners;
            const Vector3d normal = cross(b - a, c - a);
            const double n2 = dot(normal, normal);
            hit.shape_hit.u = float(dot(cross(q - a, c - a), normal) / n2);
            hit.shape_hit.v = float(dot(cross(b - a, q - a), normal) / n2);
        }
        const SurfaceContext s = surface_context(world_, ray, hit);
        const Material& m = *s.material;
        Color local = s.emission + ambient_term(m, s.ambient_color, world_.ambient());
        for (std::size_t l = 0; l < lights.size(); ++l) {
            float share = drawing.lit_share[l];
            if (share > 0) share = float(std::min(1.0, drawing.lit[l].area_at(x, y) / area));
            if (share == 0) continue;
            const LightSample ls = sample_light(lights[l], s.sp.p);
            if (dot(s.n, ls.to_light) <= 0) continue;
            local += std::abs(share) *
                     light_term(m, s.color, s.n, ls.to_light, s.to_viewer, ls.intensity);
        }
        drawing.sum(x, y) += float(area) * beam.weight * local;
    });
    for (std::size_t l = 0; l < lights.size(); ++l)
        if (drawing.lit_share[l] > 0) drawing.lit[l].clear();
}

void BeamIntegrator::draw_sky(const Paths& region, const Beam& beam, TileDrawing& drawing) const {
    const Camera& camera = world_.camera();
    drawing.fragment.add(region);
    drawing.fragment.drain([&](int x, int y, double area, double cx, double cy) {
        const Vector3d w =
            beam.from_eye.linear(Vector3d(camera.generate_ray({float(cx), float(cy)}).direction));
        const Vector3 d = normalize(w.to_float());
        drawing.sum(x, y) += float(area) * beam.weight * world_.sky().radiance(d);
    });
}

}  // namespace glint
