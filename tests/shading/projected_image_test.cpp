// POV-Ray's image_map projections with worked numbers: planar along z, spherical and
// cylindrical round y from +x towards +z, once, and the lookups they lead to.
#include "glint/shading/projected_image.h"

#include <gtest/gtest.h>

#include <cmath>

namespace glint {
namespace {

void expect_uv(ImageProjection projection, Point3 q, float u, float v, bool once = false) {
    const auto uv = projected_uv(projection, once, q);
    ASSERT_TRUE(uv.has_value()) << q.x << " " << q.y << " " << q.z;
    EXPECT_NEAR(uv->x, u, 1e-6f);
    EXPECT_NEAR(uv->y, v, 1e-6f);
}

TEST(ProjectedImage, PlanarTakesXAndYAndOnceKeepsOneCopy) {
    expect_uv(ImageProjection::planar, {0.25f, 0.75f, 5}, 0.25f, 0.75f);
    expect_uv(ImageProjection::planar, {-0.5f, 2.5f, 0}, -0.5f, 2.5f);  // wrapped by the lookup
    expect_uv(ImageProjection::planar, {0.25f, 0.75f, -3}, 0.25f, 0.75f, true);
    EXPECT_FALSE(projected_uv(ImageProjection::planar, true, {1.2f, 0.5f, 0}));
    EXPECT_FALSE(projected_uv(ImageProjection::planar, true, {0.5f, -0.1f, 0}));
    EXPECT_FALSE(projected_uv(ImageProjection::planar, true, {0.5f, 1, 0}));  // [0, 1)
}

// u from +x (0) towards +z (1/4), -x (1/2) and -z (3/4); v = 1/2 + asin(y / |q|) / pi.
TEST(ProjectedImage, SphericalIsLongitudeAndLatitude) {
    expect_uv(ImageProjection::spherical, {2, 0, 0}, 0, 0.5f);
    expect_uv(ImageProjection::spherical, {0, 0, 1}, 0.25f, 0.5f);
    expect_uv(ImageProjection::spherical, {-1, 0, 0}, 0.5f, 0.5f);
    expect_uv(ImageProjection::spherical, {0, 0, -3}, 0.75f, 0.5f);
    expect_uv(ImageProjection::spherical, {1, 1, 0}, 0, 0.75f);
    expect_uv(ImageProjection::spherical, {0, -4, 0}, 0, 0);  // a pole: any u
    EXPECT_FALSE(projected_uv(ImageProjection::spherical, false, {0, 0, 0}));
}

TEST(ProjectedImage, CylindricalIsTheAngleAndTheHeight) {
    expect_uv(ImageProjection::cylindrical, {0, 0.3f, 2}, 0.25f, 0.3f);
    expect_uv(ImageProjection::cylindrical, {1, 3.5f, 1}, 0.125f, 3.5f);
    EXPECT_FALSE(projected_uv(ImageProjection::cylindrical, true, {1, 3.5f, 1}));
    EXPECT_FALSE(projected_uv(ImageProjection::cylindrical, false, {0, 0.5f, 0}));  // the axis
}

TEST(ProjectedImage, LooksUpTheImageWhereTheProjectionSends) {
    Image two(2, 1);
    two.at(0, 0) = {1, 0, 0};
    two.at(1, 0) = {0, 0, 1};
    ProjectedImage texture;
    texture.image.image = std::make_shared<const MipMap>(std::move(two));
    texture.image.filter = TextureFilter::nearest;
    texture.outside = {0, 1, 0};
    texture.to_projection = Transform::scale(0.5f, 0.5f, 0.5f);  // the image twice as large
    EXPECT_EQ(evaluate(texture, {0.5f, 1, 0}), (Color{1, 0, 0}));
    EXPECT_EQ(evaluate(texture, {1.5f, 1, 0}), (Color{0, 0, 1}));
    EXPECT_EQ(evaluate(texture, {2.5f, 1, 0}), (Color{1, 0, 0}));  // repeated
    texture.once = true;
    EXPECT_EQ(evaluate(texture, {2.5f, 1, 0}), (Color{0, 1, 0}));
}

}  // namespace
}  // namespace glint
