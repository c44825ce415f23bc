// Ray differentials (pencil.h) against what is known: the eye's pencil and its transfer to a
// plane with worked numbers; the pencils reflected and refracted by spheres (plain and
// stretched) and the footprint they leave on a floor, against finite differences of real rays;
// and, in a render, textures filtered over the pencil's footprint at one sample a pixel against
// a supersampled reference.
#include "glint/render/pencil.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "glint/geometry/shape.h"
#include "glint/render/render.h"
#include "glint/shading/optics.h"
#include "reference_values.h"

namespace glint {
namespace {

using testing::rms_difference;

void expect_near(Vector3 a, Vector3 b, float tolerance) {
    EXPECT_NEAR(a.x, b.x, tolerance) << "x";
    EXPECT_NEAR(a.y, b.y, tolerance) << "y";
    EXPECT_NEAR(a.z, b.z, tolerance) << "z";
}

TEST(Pencil, EyePencilIsOnePixelsStepOfTheWindow) {
    CameraSpec spec;
    spec.from = {0, 0, 0};
    spec.at = {0, 0, -1};
    spec.fov = 90;  // the window at distance 1 is 2 high; 100 pixels: 0.02 a pixel
    const Camera camera(spec, 100, 100);
    const Point2 film{50, 50};
    const Ray ray = camera.generate_ray(film);
    const RayDifferential d = eye_pencil(camera, ray, film, {0.5f, 0.5f}, 0, 1);
    // A pinhole: every ray leaves the eye.
    expect_near(d.dodx, {}, 1e-7f);
    expect_near(d.dody, {}, 1e-7f);
    // (0.02, 0, -1) normalised less (0, 0, -1): 0.02 across (right is +x looking down -z), and
    // 0.02 down.
    EXPECT_NEAR(length(d.dddx), 0.02f, 1e-4f);
    EXPECT_NEAR(length(d.dddy), 0.02f, 1e-4f);
    EXPECT_NEAR(std::abs(d.dddx.x), 0.02f, 1e-4f);
    EXPECT_NEAR(std::abs(d.dddy.y), 0.02f, 1e-4f);
    // Four samples a pixel: each stands for half the step.
    EXPECT_FLOAT_EQ(eye_pencil_scale(4), 0.5f);
    EXPECT_FLOAT_EQ(eye_pencil_scale(1024), 0.125f);
}

TEST(Pencil, TransferToATiltedPlaneWorkedExample) {
    // From the origin straight down -z onto the plane through (0, 0, -5) with normal
    // (0, 0.6, 0.8), t = 5. The y step 0.01 of the direction moves the point 0.05 up; the plane
    // slopes, so the neighbour meets it dt = -(0.05 * 0.6) / -0.8 = 0.0375 further on:
    // dp/dy = (0, 0.05, 0) + 0.0375 (0, 0, -1).
    const Plane plane{{0, 0, -5}, {0, 0.6f, 0.8f}};
    const Ray ray{{0, 0, 0}, {0, 0, -1}};
    const RayDifferential d{{}, {}, {0.01f, 0, 0}, {0, 0.01f, 0}};
    const auto hit = plane.intersect(ray, {0, kInfinity});
    ASSERT_TRUE(hit);
    const SurfacePoint sp = plane.surface_at(ray, *hit);
    const PencilAtSurface at = pencil_at(ray, d, hit->t, sp);
    expect_near(at.dpdx, {0.05f, 0, 0}, 1e-6f);
    expect_near(at.dpdy, {0, 0.05f, -0.0375f}, 1e-6f);
    EXPECT_NEAR(pencil_width(at), std::hypot(0.05f, 0.0375f), 1e-6f);
    // The plane's uv are distances along two unit axes in it: the footprint is dp along them.
    EXPECT_NEAR(at.footprint.dudx, dot(at.dpdx, sp.dpdu), 1e-6f);
    EXPECT_NEAR(at.footprint.dvdy, dot(at.dpdy, sp.dpdv), 1e-6f);
    expect_near(at.dndx, {}, 0);  // flat
}

// A ray and its neighbours a small step h along the pencil either way: finite differences of
// what happens to real rays, to set against the pencil's derivatives.
struct Neighbours {
    Ray minus, plus;
    float h;
};
Neighbours neighbours(const Ray& ray, Vector3 dorigin, Vector3 ddirection, float h) {
    return {Ray{ray.origin - dorigin * h, normalize(ray.direction - ddirection * h)},
            Ray{ray.origin + dorigin * h, normalize(ray.direction + ddirection * h)}, h};
}

struct Meeting {
    float t;
    SurfacePoint sp;
};
Meeting meet(const Shape& shape, const Ray& ray) {
    const auto hit = intersect(shape, ray, {1e-4f, kInfinity});
    EXPECT_TRUE(hit) << shape_name(shape) << " from (" << ray.origin.x << ", " << ray.origin.y
                     << ", " << ray.origin.z << ") along (" << ray.direction.x << ", "
                     << ray.direction.y << ", " << ray.direction.z << ")";
    if (!hit) return {0, {}};
    return {hit->t, surface_at(shape, ray, *hit, Uv::compute)};
}

Vector3 central(Vector3 minus, Vector3 plus, float h) { return (plus - minus) / (2 * h); }
Vector3 central(Point3 minus, Point3 plus, float h) { return (plus - minus) / (2 * h); }

Vector3 mirror(const Ray& ray, const SurfacePoint& sp) {
    return normalize(reflect(ray.direction, face_forward(sp.shading_normal, -ray.direction)));
}

// The eye ray through a camera's film point and its pencil, a camera of 64 pixels looking at
// the shapes from z = 0 towards -z.
struct EyeRay {
    Ray ray;
    RayDifferential pencil;
};
EyeRay eye_ray(Point2 film) {
    CameraSpec spec;
    spec.from = {0, 0, 0};
    spec.at = {0, 0, -1};
    spec.fov = 40;
    const Camera camera(spec, 64, 64);
    const Ray ray = camera.generate_ray(film);
    return {ray, eye_pencil(camera, ray, film, {0.5f, 0.5f}, 0, 1)};
}

// The reflected pencil off `shape` seen through film point `film`, and its footprint on the
// plane y = -3 below, each against finite differences of real rays.
void expect_reflection_matches_real_rays(const Shape& shape, Point2 film) {
    const auto [ray, pencil] = eye_ray(film);
    const Meeting m = meet(shape, ray);
    const PencilAtSurface at = pencil_at(ray, pencil, m.t, m.sp);
    ASSERT_TRUE(at.bends_known);
    const Normal3 n = face_forward(m.sp.shading_normal, -ray.direction);
    const float side = dot(m.sp.shading_normal, n) > 0 ? 1.0f : -1.0f;
    const RayDifferential reflected = reflected_pencil(ray, pencil, at, n, side);
    const Ray bounced{m.sp.p, mirror(ray, m.sp)};
    const Plane floor{{0, -3, 0}, {0, 1, 0}};
    const Meeting on_floor = meet(floor, bounced);
    const PencilAtSurface there = pencil_at(bounced, reflected, on_floor.t, on_floor.sp);
    for (const bool across : {true, false}) {
        SCOPED_TRACE(across ? "across" : "down");
        const Neighbours nb = across ? neighbours(ray, pencil.dodx, pencil.dddx, 0.05f)
                                     : neighbours(ray, pencil.dody, pencil.dddy, 0.05f);
        const Meeting a = meet(shape, nb.minus), b = meet(shape, nb.plus);
        const float scale = length(across ? at.dpdx : at.dpdy);
        expect_near(across ? at.dpdx : at.dpdy, central(a.sp.p, b.sp.p, nb.h), 0.01f * scale);
        const Vector3 ra = mirror(nb.minus, a.sp), rb = mirror(nb.plus, b.sp);
        const Vector3 dr = across ? reflected.dddx : reflected.dddy;
        expect_near(dr, central(ra, rb, nb.h), 0.01f * length(dr));
        // And onwards to the floor: the point and its uv.
        const Meeting fa = meet(floor, Ray{a.sp.p, ra}), fb = meet(floor, Ray{b.sp.p, rb});
        const Vector3 dp = across ? there.dpdx : there.dpdy;
        expect_near(dp, central(fa.sp.p, fb.sp.p, nb.h), 0.01f * length(dp));
        const float du = across ? there.footprint.dudx : there.footprint.dudy;
        const float dv = across ? there.footprint.dvdx : there.footprint.dvdy;
        EXPECT_NEAR(du, (fb.sp.uv.x - fa.sp.uv.x) / (2 * nb.h), 0.01f * length(dp));
        EXPECT_NEAR(dv, (fb.sp.uv.y - fa.sp.uv.y) / (2 * nb.h), 0.01f * length(dp));
    }
    // The floor is farther than the eye, and the mirror convex: the pencil has spread.
    EXPECT_GT(pencil_width(there), 2 * pencil_width(at));
}

TEST(Pencil, ReflectionOffASphereMatchesRealRays) {
    const Shape ball = Sphere{{0, 0, -6}, 1.5f};
    expect_reflection_matches_real_rays(ball, {28, 38});
    expect_reflection_matches_real_rays(ball, {36, 40});
}

TEST(Pencil, ReflectionOffAStretchedSphereMatchesRealRays) {
    // An ellipsoid: the normal's change passes through the inverse transpose and its
    // renormalisation.
    const Shape egg = Transformed(Transform::translate({0, 0, -6}) * Transform::scale(2, 1, 1.2f),
                                  std::make_shared<const Shape>(Sphere{{0, 0, 0}, 1}));
    expect_reflection_matches_real_rays(egg, {30, 38});
    expect_reflection_matches_real_rays(egg, {40, 36});
}

TEST(Pencil, ReflectionOffCylindersAndConesMatchesRealRays) {
    // Upright, and leaning so the axis is no world axis.
    const Shape column = Cylinder{{0, -2, -6}, {0, 2, -6}, 1.5f};
    expect_reflection_matches_real_rays(column, {28, 56});
    const Shape leaning = Cylinder{{-1, -2, -7}, {1, 2, -5}, 1.5f};
    expect_reflection_matches_real_rays(leaning, {36, 52});
    // Widening upwards, so that its side faces down towards the floor.
    const Shape cone = Cone{{0, -2, -6}, 0.5f, {0, 2, -6}, 2};
    expect_reflection_matches_real_rays(cone, {30, 54});
}

TEST(Pencil, RefractionIntoAGlassBallMatchesRealRays) {
    const Shape ball = Sphere{{0, 0, -6}, 1.5f};
    constexpr float kEta = 1 / 1.5f;
    const auto [ray, pencil] = eye_ray({36, 26});
    const Meeting m = meet(ball, ray);
    const PencilAtSurface at = pencil_at(ray, pencil, m.t, m.sp);
    const Normal3 n = face_forward(m.sp.shading_normal, -ray.direction);
    auto refracted = [&](const Ray& r, const SurfacePoint& sp) {
        return normalize(
            *refract(r.direction, face_forward(sp.shading_normal, -r.direction), kEta));
    };
    const RayDifferential bent =
        refracted_pencil(ray, pencil, at, n, 1, kEta, refracted(ray, m.sp));
    for (const bool across : {true, false}) {
        SCOPED_TRACE(across ? "across" : "down");
        const Neighbours nb = across ? neighbours(ray, pencil.dodx, pencil.dddx, 0.05f)
                                     : neighbours(ray, pencil.dody, pencil.dddy, 0.05f);
        const Meeting a = meet(ball, nb.minus), b = meet(ball, nb.plus);
        const Vector3 dt = across ? bent.dddx : bent.dddy;
        expect_near(dt, central(refracted(nb.minus, a.sp), refracted(nb.plus, b.sp), nb.h),
                    0.01f * length(dt));
    }
    // Glass converges the pencil: the refracted directions spread less than the mirror's.
    const RayDifferential mirrored = reflected_pencil(ray, pencil, at, n, 1);
    EXPECT_LT(length(bent.dddx), length(mirrored.dddx));
}

TEST(Pencil, ShapesThatDoNotSayHowTheyBendDropThePencil) {
    // A torus gives no derivatives: a pencil reaching it keeps its point steps but no bend.
    const Shape ring = Torus{{0, 0, -6}, {0, 0, 1}, 1.5f, 0.5f};
    const auto [ray, pencil] = eye_ray({50, 32});
    const auto hit = intersect(ring, ray, {0, kInfinity});
    ASSERT_TRUE(hit);
    const SurfacePoint sp = surface_at(ring, ray, *hit, Uv::compute);
    const PencilAtSurface at = pencil_at(ray, pencil, hit->t, sp);
    EXPECT_FALSE(at.bends_known);
    EXPECT_GT(pencil_width(at), 0);
}

// A floor under a checkerboard (8 texels a check, 8 checks a unit), seen at a slant into the
// distance, where many checks fall in a pixel; a mirror ball shows it again.
Scene checkered_floor(TextureFilter filter, int samples) {
    Image checks(64, 64);
    for (int y = 0; y < 64; ++y)
        for (int x = 0; x < 64; ++x) checks.at(x, y) = Color::gray(float((x / 8 + y / 8) % 2));
    Scene scene;
    scene.settings.width = 64;
    scene.settings.height = 48;
    scene.settings.integrator = IntegratorKind::whitted;
    scene.settings.samples_per_pixel = samples;
    scene.settings.filter = FilterSpec{FilterKind::box, 0.5f};
    scene.camera.from = {0, 1, 0};
    scene.camera.at = {0, 0.2f, -4};
    scene.camera.fov = 50;
    Material floor;
    floor.ka = 1;
    floor.kd = 0;
    floor.ks = 0;
    floor.color = ImageTexture{
        std::make_shared<const MipMap>(std::move(checks)), {1, 1, 1}, TextureWrap::repeat, filter};
    Material mirror;
    mirror.ka = 0;
    mirror.kd = 0;
    mirror.ks = 0;
    mirror.reflect = 1;
    scene.materials = {floor, mirror};
    scene.ambient = {1, 1, 1};
    scene.objects.push_back({Plane{{0, 0, 0}, {0, 1, 0}}, 0});
    scene.objects.push_back({Sphere{{0.8f, 0.5f, -3}, 0.5f}, 1});
    return scene;
}

TEST(Pencil, FilteredTexturesAtOneSampleComeCloseToASupersampledImage) {
    // The reference: 256 jittered samples a pixel of the unfiltered texture. One sample of it
    // aliases; one sample filtered over the pencil's footprint (in the mirror too) does not.
    const Image reference = render(World(checkered_floor(TextureFilter::bilinear, 256)), {}).image;
    const Image point = render(World(checkered_floor(TextureFilter::bilinear, 1)), {}).image;
    const Image trilinear = render(World(checkered_floor(TextureFilter::trilinear, 1)), {}).image;
    const Image ewa = render(World(checkered_floor(TextureFilter::ewa, 1)), {}).image;
    const float aliased = rms_difference(point, reference);
    EXPECT_GT(aliased, 0.2f);
    EXPECT_LT(rms_difference(trilinear, reference), aliased / 3);
    EXPECT_LT(rms_difference(ewa, reference), aliased / 3);
    // EWA does not blur the distance as trilinear filtering does.
    EXPECT_LT(rms_difference(ewa, reference), rms_difference(trilinear, reference));
}

}  // namespace
}  // namespace glint
