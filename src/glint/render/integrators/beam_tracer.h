// Heckbert and Hanrahan's beam tracing (1984), for scenes of planar polygons: the view pyramid of
// each tile is swept through the scene as a beam, a region of the image. The polygons it meets,
// nearest first (a BSP tree's order from the beam's eye), each take from it the part of the
// region they cover, a fragment; a mirror's fragment starts a reflected beam, whose polygons
// are seen through the mirror image of the eye, and glass a refracted one, through the apparent-
// depth map of the paraxial approximation. The beam tree so built is drawn with each fragment's
// exact area in each pixel (no aliasing at polygon edges, nor at shadow edges: lights reach a
// polygon where the shadow polygons of the others leave it, shadow_regions.h); a pixel is
// shaded once per fragment, at the centroid of the fragment's part of it, by the notes' Phong
// terms with reflection and transmission weighted by kr and kt.
#pragma once

#include <memory>
#include <span>
#include <vector>

#include "glint/math/color.h"
#include "glint/render/beam/polygon_bsp.h"
#include "glint/render/beam/shadow_regions.h"
#include "glint/render/film/film.h"
#include "glint/render/integrators/whitted.h"
#include "glint/render/tiles.h"

namespace glint {

class BeamIntegrator {
public:
    // The scene's polygons, their BSP tree and where each light reaches them: built once.
    struct Polygons {
        double scale = 1;      // integer units per scene unit in the polygons' planes
        double tolerance = 0;  // scene units within which a point is on a plane
        std::vector<beam::BeamPolygon> polygons;
        beam::PolygonBsp bsp;
        std::vector<std::vector<beam::LightReach>> reach;  // [light][polygon]
    };
    using Shared = std::shared_ptr<const Polygons>;
    // The world must be fit for beam tracing (check_integrator_fits).
    static Shared prepare(const World& world);

    BeamIntegrator(const World& world, const Shared& shared)
        : world_(world), polygons_(*shared), whitted_(world) {}

    // Traces the tile's beam tree and adds each pixel's colour to the film: the render loop's
    // call for an integrator that draws whole tiles. Counts each beam as a ray of its kind.
    void draw_tile(const Tile& tile, FilmTile& film, RayStats& stats);

    // A single ray is a beam of no width, whose tree is Whitted's (but for refraction, which
    // a ray follows by Snell's law where beams take the paraxial map).
    Color trace_eye_ray(const Ray& ray, const RayDifferential* pencil, SampleStream& stream,
                        RayStats& stats) {
        return whitted_.trace_eye_ray(ray, pencil, stream, stats);
    }
    // Beams are not rays: explain and the output variables are refused for this integrator
    // before a render starts.
    void record_into(RayRecorder*) {}

private:
    struct Beam;
    struct TileDrawing;
    void trace_beam(const Beam& beam, TileDrawing& drawing, std::vector<Beam>& beams,
                    RayStats& stats) const;
    // The half-spaces a beam sees into (world space): beyond its mirror or refracting plane,
    // and within the pyramid from the eye through its region.
    std::vector<beam::PlaneD> bounds_of_beam(const Beam& beam) const;
    // The part of a region of a plane within them all.
    static beam::Paths clipped(const beam::PlaneFrame& frame, beam::Paths region,
                               std::span<const beam::PlaneD> bounds);
    beam::Paths projected(const beam::PlaneFrame& frame, const beam::Paths& region,
                          const Beam& beam) const;
    void draw_fragment(const beam::Paths& fragment, const beam::BeamPolygon& polygon,
                       std::uint32_t polygon_index, const Beam& beam,
                       std::span<const beam::PlaneD> bounds, TileDrawing& drawing) const;
    void draw_sky(const beam::Paths& region, const Beam& beam, TileDrawing& drawing) const;

    const World& world_;
    const Polygons& polygons_;
    WhittedIntegrator whitted_;
};

}  // namespace glint
