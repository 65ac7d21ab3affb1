// The zoom of a camera path's field of view, as the tile renderer applies it to every tile's rays
// (cluster::wallToPlanet): a zoom of 2 shows the centre half of the unzoomed view, and a key's field of
// view is the angle the zoomed wall spans from its eye.
#include "physics/constants.h"
#include "cluster/frame_state.h"
#include "scene/camera_path.h"
#include "wall/tile_rays.h"
#include "wall/wall.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace aurorawall;

namespace {

// A 2x2 wall of 320x180 screens with 10 mm bezels, the eye 600 mm in front of its centre.
wall::Wall testWall()
{
    wall::GridSpec grid;
    grid.columns = 2;
    grid.rows = 2;
    grid.screenPx = {320, 180};
    grid.screenMm = {320.0, 180.0};
    grid.bezelMm = {10.0, 10.0};
    grid.eyeFromCentreMm = {0.0, 0.0, 600.0};
    return wall::makeGridWall(grid);
}

// A camera turned away from the planet axes, so that the rotation is not trivial.
cluster::FrameState frame(double zoom)
{
    cluster::FrameState s;
    const glm::dvec3 forward = glm::normalize(glm::dvec3(0.3, 0.8, 0.5));
    s.cameraUp = glm::normalize(glm::dvec3(0.0, -0.5, 0.8) - forward * glm::dot(glm::dvec3(0.0, -0.5, 0.8), forward));
    s.cameraRight = glm::cross(forward, s.cameraUp);
    s.cameraBack = -forward;
    s.zoom = zoom;
    return s;
}

// The unit direction (planet frame) of canvas point canvasPx on the screen's rays, as the renderer
// forms it: each ray vector through wallToPlanet, then originDir + x stepRight + y stepDown.
glm::dvec3 direction(const wall::TileRays& rays, const cluster::FrameState& s, glm::dvec2 canvasPx)
{
    const glm::dmat3 m = cluster::wallToPlanet(s);
    return glm::normalize(m * rays.originDir + canvasPx.x * (m * rays.stepRight) + canvasPx.y * (m * rays.stepDown));
}

double angleDeg(const glm::dvec3& a, const glm::dvec3& b)
{
    return std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b)) * 180.0 / aurorawall::physics::kPi;
}

} // namespace

TEST(ZoomRays, ZoomTwoShowsTheCentreHalfOfTheView)
{
    const wall::Wall w = testWall();
    ASSERT_TRUE(w.sharedCanvas);
    const wall::TileRays rays = wall::tileRays(w, 0);
    const glm::dvec2 size(w.canvasSizePx);
    const cluster::FrameState wide = frame(1.0), zoomed = frame(2.0);
    // The centre of the canvas (in front of the eye) looks the same way.
    EXPECT_LT(angleDeg(direction(rays, wide, size / 2.0), direction(rays, zoomed, size / 2.0)), 1e-12);
    // The unzoomed view's quarter points are the zoomed view's corners and edge midpoints.
    const glm::dvec2 points[] = {{0.0, 0.0}, {1.0, 1.0}, {0.0, 1.0}, {1.0, 0.0}, {0.5, 0.0}, {0.0, 0.5}};
    for (const glm::dvec2& p : points) {
        const glm::dvec3 quarter = direction(rays, wide, size * (0.25 + 0.5 * p));
        const glm::dvec3 edge = direction(rays, zoomed, size * p);
        EXPECT_LT(angleDeg(quarter, edge), 1e-12) << p.x << ", " << p.y;
    }
    // And a point outside the centre half is not on the zoomed canvas's edge.
    EXPECT_GT(angleDeg(direction(rays, wide, size * 0.2), direction(rays, zoomed, {0.0, 0.0})), 1.0);
}

TEST(ZoomRays, AKeysFieldOfViewIsTheAngleTheZoomedWallSpans)
{
    const wall::Wall w = testWall();
    const wall::TileRays rays = wall::tileRays(w, 0);
    const double height = w.canvasSizePx.y, middle = w.canvasSizePx.x / 2.0;
    // The wall's own: 370 mm high (bezel included) at 600 mm.
    const double tanHalf = wall::tanHalfVerticalFieldOfView(w);
    EXPECT_DOUBLE_EQ(tanHalf, 185.0 / 600.0);
    for (double fov : {5.0, 34.3, 60.0, 120.0, 170.0}) {
        const cluster::FrameState s = frame(scene::zoomOf(fov, tanHalf));
        const double spanned = angleDeg(direction(rays, s, {middle, 0.0}), direction(rays, s, {middle, height}));
        EXPECT_NEAR(spanned, fov, 1e-11) << fov;
    }
}

// At zoom 1 the wall-to-planet rotation is the camera's basis itself, so every tile's rays are those
// of an unzoomed wall bit for bit.
TEST(ZoomRays, ZoomOneLeavesTheRaysBitForBit)
{
    const cluster::FrameState s = frame(1.0);
    EXPECT_EQ(cluster::wallToPlanet(s), glm::dmat3(s.cameraRight, s.cameraUp, s.cameraBack));
}
