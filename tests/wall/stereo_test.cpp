// Stereo: each screen's rays start at the eye it shows. The disparity of a point, measured on the
// screens through the pixel rays, equals the one similar triangles give.
#include "wall/frustum.h"
#include "wall/tile_rays.h"
#include "wall/wall_file.h"

#include <gtest/gtest.h>

namespace aurorawall::wall {
namespace {

constexpr double kInterocularMm = 63.0, kEyeDistanceMm = 2500.0;

Wall shippedStereo() { return loadWall(std::string(WALL_CONFIG_DIR) + "/stereo-2x1.toml"); }

// The x coordinate (mm, wall plane) where the ray of `screen` through point p crosses the screen:
// the pixel ray whose direction is parallel to p - eye, with eye the position the test expects.
double screenX(const Wall& wall, int screen, glm::dvec3 eye, glm::dvec3 p)
{
    const TileRays rays = tileRays(wall, screen);
    const glm::dvec3 v = p - eye;
    // Rays are originDir + px stepRight + py stepDown with constant z: scale v to that z.
    const glm::dvec3 direction = v * (rays.originDir.z / v.z);
    const double canvasPx = (direction.x - rays.originDir.x) / rays.stepRight.x;
    const double localPx = canvasPx - rays.pixelOffset.x;
    return wall.screens[screen].lowerLeftMm.x + localPx * wall.screens[screen].pixelPitchMm().x;
}

TEST(Stereo, ShippedPassiveStereoWall)
{
    const Wall wall = shippedStereo();
    ASSERT_EQ(wall.screens.size(), 2u);
    EXPECT_EQ(wall.screens[0].eye, Eye::left);
    EXPECT_EQ(wall.screens[1].eye, Eye::right);
    EXPECT_EQ(wall.interocularMm, kInterocularMm);
    // The gathered canvas holds the two eyes side by side.
    EXPECT_EQ(wall.canvasSizePx, glm::ivec2(3840, 1080));
    EXPECT_EQ(wall.screens[1].canvasOffsetPx, glm::ivec2(1920, 0));
    EXPECT_EQ(wall.eyeOf(wall.screens[0]), wall.eyeMm - glm::dvec3(kInterocularMm / 2, 0.0, 0.0));
    EXPECT_EQ(wall.eyeOf(wall.screens[1]), wall.eyeMm + glm::dvec3(kInterocularMm / 2, 0.0, 0.0));
}

// Similar triangles: eyes I apart at distance E from the screen see a point at depth z (z < 0
// behind the screen) at screen positions x_R - x_L = I (-z) / (E - z) apart.
TEST(Stereo, DisparityIsTheSimilarTrianglesOne)
{
    const Wall wall = shippedStereo();
    const glm::dvec3 centreEye{1000.0, 562.5, kEyeDistanceMm};
    const glm::dvec3 leftEye = centreEye - glm::dvec3(kInterocularMm / 2, 0, 0);
    const glm::dvec3 rightEye = centreEye + glm::dvec3(kInterocularMm / 2, 0, 0);
    for (double z : {-10000.0, -2500.0, -100.0, 0.0, 1250.0}) {
        const glm::dvec3 p{700.0, 300.0, z};
        const double disparity = screenX(wall, 1, rightEye, p) - screenX(wall, 0, leftEye, p);
        EXPECT_NEAR(disparity, kInterocularMm * -z / (kEyeDistanceMm - z), 1e-9) << "z = " << z;
    }
    // Far behind the screen the disparity tends to the interocular distance, on it to zero.
    EXPECT_NEAR(screenX(wall, 1, rightEye, {700, 300, 0}) - screenX(wall, 0, leftEye, {700, 300, 0}), 0.0, 1e-9);
}

// The frustum of each eye (Kooima's generalized perspective projection from its own eye) maps a
// point to the pixel whose ray passes through it.
TEST(Stereo, EachEyesFrustumAgreesWithItsRays)
{
    const Wall wall = shippedStereo();
    const glm::dvec3 p{1300.0, 800.0, -4000.0};
    for (int i = 0; i < 2; ++i) {
        const Screen& s = wall.screens[i];
        const Frustum f = offAxisFrustum(s, wall.eyeOf(s), 10.0, 1e6);
        const glm::dvec4 clip = f.projection * f.view * glm::dvec4(p, 1.0);
        const double ndcX = clip.x / clip.w;
        const double xMm = s.lowerLeftMm.x + (ndcX + 1.0) / 2.0 * s.widthMm;
        EXPECT_NEAR(xMm, screenX(wall, i, wall.eyeOf(s), p), 1e-9);
    }
}

TEST(Stereo, SingleScreenEquivalentKeepsBothEyes)
{
    const Wall single = singleScreenEquivalent(shippedStereo());
    ASSERT_EQ(single.screens.size(), 2u);
    EXPECT_EQ(single.canvasSizePx, glm::ivec2(3840, 1080));
    EXPECT_EQ(single.interocularMm, kInterocularMm);
    EXPECT_EQ(single.screens[1].eye, Eye::right);
    EXPECT_EQ(single.screens[1].canvasOffsetPx, glm::ivec2(1920, 0));
}

TEST(Stereo, SingleScreenEquivalentOfOneEyeKeepsThatEye)
{
    Wall wall = shippedStereo();
    wall.screens.pop_back();
    wall = assembleWall(wall.screens, wall.eyeMm);
    const Wall single = singleScreenEquivalent(wall);
    ASSERT_EQ(single.screens.size(), 1u);
    EXPECT_EQ(single.screens[0].eye, Eye::left);
}

// A side-by-side screen's halves are the two eyes' views of the whole screen at half the columns.
TEST(Stereo, SideBySideHalvesAreTheEyesViewsOfTheWholeScreen)
{
    Screen s;
    s.widthPx = 320;
    s.heightPx = 90;
    s.widthMm = 80.0;
    s.heightMm = 45.0;
    s.eye = Eye::sideBySide;
    Wall sideBySide = assembleWall({s}, {40.0, 22.5, 600.0});
    sideBySide.interocularMm = kInterocularMm;
    s.widthPx = 160;
    s.eye = Eye::left;
    Screen right = s;
    right.eye = Eye::right;
    Wall eyes = assembleWall({s, right}, {40.0, 22.5, 600.0});
    eyes.interocularMm = kInterocularMm;

    const TileRays both = tileRays(sideBySide, 0), left = tileRays(eyes, 0), rightRays = tileRays(eyes, 1);
    for (double x : {0.5, 17.5, 159.5})
        for (double y : {0.5, 44.5, 89.5}) {
            const glm::dvec3 l = rayDirection(both, glm::dvec2(x, y)), r = rayDirection(both, glm::dvec2(160.0 + x, y));
            const glm::dvec3 lExpected = rayDirection(left, glm::dvec2(x, y));
            const glm::dvec3 rExpected = rayDirection(rightRays, glm::dvec2(x, y));
            EXPECT_NEAR(glm::length(l - lExpected), 0.0, 1e-12 * glm::length(lExpected)) << x << ", " << y;
            EXPECT_NEAR(glm::length(r - rExpected), 0.0, 1e-12 * glm::length(rExpected)) << x << ", " << y;
        }
}

} // namespace
} // namespace aurorawall::wall
