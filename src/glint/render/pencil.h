// A ray's pencil (Shinya, Takahashi and Naito 1987) in its modern form, ray differentials (Igehy
// 1999): how a ray's origin and direction change from one pixel to the next, carried to the
// surface it meets and through mirror reflection and refraction there. Where it meets a surface
// it gives the footprint a texture lookup filters over, and how wide the pencil has grown.
#pragma once

#include "glint/camera/camera.h"
#include "glint/geometry/surface_point.h"
#include "glint/math/ray.h"

namespace glint {

struct RayDifferential {
    Vector3 dodx, dody;  // the origin's change a pixel across (x) and down (y) the image
    Vector3 dddx, dddy;  // the unit direction's
};

// The pencil where it meets a surface.
struct PencilAtSurface {
    Vector3 dpdx, dpdy;     // the hit point's change, in the tangent plane
    UvFootprint footprint;  // uv's change; zero where the shape gives no dp/du, dp/dv
    Vector3 dndx, dndy;     // the shading normal's; zero on flat faces
    // Whether the shape told how its normal bends (SurfacePoint::has_derivatives): without it
    // a reflected or refracted pencil cannot be known, and is dropped.
    bool bends_known = false;
};

// The pencil of the eye ray `ray` through `film`: the differences to the rays a pixel to the
// right and a pixel down through the same lens point at the same moment, times `scale` (less
// than 1 when several samples share a pixel, each then standing for a smaller part of it).
RayDifferential eye_pencil(const Camera& camera, const Ray& ray, Point2 film, Point2 lens,
                           float time, float scale);

// Each of a pixel's `samples` eye rays stands for a pencil 1/sqrt(samples) as wide, but never
// narrower than an eighth of the pixel's (as pbrt does): a finer footprint than that only
// brings back the aliasing the filter is there to remove.
float eye_pencil_scale(int samples);

// Transfer to the surface point sp that the ray meets at distance t (Igehy's eq. 10-11): the
// neighbouring rays meet the tangent plane at p + dp. Footprint and the normal's change follow
// from the shape's dp/du, dp/dv and dn/du, dn/dv.
PencilAtSurface pencil_at(const Ray& ray, const RayDifferential& pencil, float t,
                          const SurfacePoint& sp);

// The pencils of the mirror-reflected and refracted rays at `at` (Igehy's eq. 14 and 17-19):
// n is the unit shading normal turned towards the incoming ray, and `side` -1 where it was
// turned (the normal's change turns with it); eta = n1 / n2 and `refracted` the unit refracted
// direction.
RayDifferential reflected_pencil(const Ray& ray, const RayDifferential& pencil,
                                 const PencilAtSurface& at, Normal3 n, float side);
RayDifferential refracted_pencil(const Ray& ray, const RayDifferential& pencil,
                                 const PencilAtSurface& at, Normal3 n, float side, float eta,
                                 Vector3 refracted);

// How wide the pencil is where it meets the surface: the longer of its two steps, in scene
// units.
float pencil_width(const PencilAtSurface& at);

}  // namespace glint
