// Dome masters: the angular fisheye of the whole canvas, checked in double against its definition
// (the angle from the axis is |offset| * FOV / canvas height, the azimuth that of the offset).
#include "physics/constants.h"
#include "wall/tile_rays.h"
#include "wall/wall_file.h"

#include <gtest/gtest.h>

#include <cmath>

namespace aurorawall::wall {
namespace {


// Angle between two directions, accurate near 0 and pi alike.
double angleBetween(glm::dvec3 a, glm::dvec3 b) { return std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b)); }

// A 512x512 dome master cut into two 256x512 screens.
Wall domeWall(double fieldOfViewDeg, double tiltDeg)
{
    GridSpec g;
    g.columns = 2;
    g.screenPx = {256, 512};
    g.screenMm = {256.0, 512.0};
    Wall wall = makeGridWall(g);
    wall.projection = Projection::dome;
    wall.dome = {fieldOfViewDeg, tiltDeg};
    return wall;
}

TEST(Dome, CentreRayIsTheAxisAndTheTiltRaisesIt)
{
    for (double tilt : {0.0, 30.0, 90.0, -45.0}) {
        const TileRays rays = tileRays(domeWall(180.0, tilt), 1);
        const glm::dvec3 axis = domeDirection(rays, {256.0, 256.0});
        // The camera looks along -z with +y up; the tilt turns the axis up about +x.
        const double t = tilt * aurorawall::physics::kPi / 180.0;
        EXPECT_NEAR(glm::length(axis - glm::dvec3(0.0, std::sin(t), -std::cos(t))), 0.0, 1e-15) << tilt;
    }
}

TEST(Dome, RimIsAtHalfTheFieldOfView)
{
    for (double fov : {30.0, 180.0, 220.0, 360.0}) {
        const TileRays rays = tileRays(domeWall(fov, 20.0), 0);
        const glm::dvec3 axis = domeDirection(rays, {256.0, 256.0});
        // The rim: 256 px (half the canvas height) from the centre, in eight directions.
        for (int k = 0; k < 8; ++k) {
            const double phi = k * aurorawall::physics::kPi / 4.0;
            const glm::dvec3 rim = domeDirection(rays, glm::dvec2(256.0) + 256.0 * glm::dvec2(std::cos(phi), std::sin(phi)));
            EXPECT_NEAR(glm::length(rim), 1.0, 1e-15);
            EXPECT_NEAR(angleBetween(rim, axis), fov / 2.0 * aurorawall::physics::kPi / 180.0, 1e-12) << fov << " deg, azimuth " << k;
        }
        // Half way out: a quarter of the field of view.
        EXPECT_NEAR(angleBetween(domeDirection(rays, {256.0 + 128.0, 256.0}), axis), fov / 4.0 * aurorawall::physics::kPi / 180.0, 1e-12);
    }
}

TEST(Dome, FullSphereRimLooksOppositeTheAxis)
{
    const TileRays rays = tileRays(domeWall(360.0, 0.0), 0);
    for (glm::dvec2 rim : {glm::dvec2(512.0, 256.0), glm::dvec2(256.0, 0.0), glm::dvec2(0.0, 256.0)})
        EXPECT_NEAR(glm::length(domeDirection(rays, rim) - glm::dvec3(0.0, 0.0, 1.0)), 0.0, 1e-12);
}

// Seen from inside, as a camera sees: right of the centre looks right (+x), above looks up (+y),
// and the azimuth in the image (from image-right toward image-down) is that of the view.
TEST(Dome, AzimuthRunsAsTheImage)
{
    const TileRays rays = tileRays(domeWall(180.0, 0.0), 0);
    const glm::dvec3 right = domeDirection(rays, {256.0 + 100.0, 256.0});
    EXPECT_GT(right.x, 0.0);
    EXPECT_NEAR(right.y, 0.0, 1e-15);
    const glm::dvec3 up = domeDirection(rays, {256.0, 256.0 - 100.0});
    EXPECT_GT(up.y, 0.0);
    EXPECT_NEAR(up.x, 0.0, 1e-15);
    for (double phiDeg : {10.0, 100.0, 200.0, 300.0}) {
        const double phi = phiDeg * aurorawall::physics::kPi / 180.0;
        const glm::dvec3 d = domeDirection(rays, glm::dvec2(256.0) + 150.0 * glm::dvec2(std::cos(phi), std::sin(phi)));
        // Image-down is -y for tilt 0.
        EXPECT_NEAR(std::atan2(-d.y, d.x), std::atan2(std::sin(phi), std::cos(phi)), 1e-12) << phiDeg;
    }
}

TEST(Dome, OutsideTheCircleIsNoRay)
{
    const TileRays rays = tileRays(domeWall(180.0, 0.0), 0);
    EXPECT_EQ(domeDirection(rays, {0.5, 0.5}), glm::dvec3(0.0));
    EXPECT_EQ(domeDirection(rays, {256.0 + 256.001, 256.0}), glm::dvec3(0.0));
    EXPECT_NE(domeDirection(rays, {256.0 + 255.999, 256.0}), glm::dvec3(0.0));
}

// Every tile gets the constants of the whole canvas, and its canvas offset, so a pixel's ray does
// not depend on which screen (or band of it) draws it.
TEST(Dome, EveryScreenSharesTheCanvasFisheye)
{
    const Wall wall = domeWall(180.0, 10.0);
    const TileRays a = tileRays(wall, 0), b = tileRays(wall, 1, {0, 100});
    EXPECT_TRUE(a.dome && b.dome);
    EXPECT_EQ(a.domeCentrePx, b.domeCentrePx);
    EXPECT_EQ(a.domeRadiansPerPx, b.domeRadiansPerPx);
    EXPECT_EQ(a.domeAxis, b.domeAxis);
    EXPECT_EQ(a.pixelOffset, glm::ivec2(0, 0));
    EXPECT_EQ(b.pixelOffset, glm::ivec2(256, 100));
    const Wall single = singleScreenEquivalent(wall);
    const TileRays whole = tileRays(single, 0);
    EXPECT_EQ(whole.domeCentrePx, a.domeCentrePx);
    EXPECT_EQ(whole.domeRadiansPerPx, a.domeRadiansPerPx);
}

TEST(Dome, ShippedDome180)
{
    const Wall wall = loadWall(std::string(WALL_CONFIG_DIR) + "/dome-180.toml");
    EXPECT_EQ(wall.projection, Projection::dome);
    EXPECT_EQ(wall.dome.fieldOfViewDeg, 180.0);
    EXPECT_EQ(wall.canvasSizePx, glm::ivec2(512, 512));
    EXPECT_EQ(wall.rankCount, 2);
}

} // namespace
} // namespace aurorawall::wall
