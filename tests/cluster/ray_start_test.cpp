// Where a frame's rays start (cluster::rayStart): at a camera near the scene; for a far camera, moved
// forward along every ray to at least twice the scene's reach from the centre, never past anything.
#include "cluster/frame_state.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace aurorawall;

namespace {

cluster::FrameState lookingFrom(glm::dvec3 positionKm, glm::dvec3 forward)
{
    cluster::FrameState s;
    s.cameraPositionKm = positionKm;
    s.cameraBack = -glm::normalize(forward);
    return s;
}

} // namespace

TEST(RayStart, ANearCameraStartsTheRays)
{
    const glm::dvec3 camera(0.0, 6371.0 + 150.0, 0.0);
    const cluster::RayStart start = cluster::rayStart(lookingFrom(camera, {1.0, 0.0, 0.0}), 6671.0);
    EXPECT_EQ(start.distanceKm, 0.0);
    EXPECT_EQ(start.pointKm, camera);
}

// Every ray's start, pointKm + distanceKm (d - forward), lies on the ray at distanceKm from the camera;
// no point within the reach radius lies nearer the camera than that (so the start passes nothing of the
// scene), and the start itself lies at least twice the reach from the centre.
TEST(RayStart, AFarCamerasRaysStartBeyondTheSceneAndBeforeIt)
{
    const double reach = 6671.0;
    const glm::dvec3 camera(3e7, -9e7, 2e7);
    const glm::dvec3 forward = glm::normalize(-camera + glm::dvec3(0.0, 0.0, 6000.0));
    const cluster::RayStart start = cluster::rayStart(lookingFrom(camera, forward), reach);
    const double distance = glm::length(camera);
    EXPECT_NEAR(glm::length(start.forward - forward), 0.0, 1e-15);
    EXPECT_GT(start.distanceKm, 0.0);
    EXPECT_LE(start.distanceKm, distance - reach); // the nearest point of the reach sphere
    for (const glm::dvec3 d : {forward, glm::normalize(forward + glm::dvec3(1e-4, 0.0, 0.0)),
                               glm::normalize(forward + glm::dvec3(0.0, -1e-3, 2e-3)), glm::dvec3(1.0, 0.0, 0.0),
                               -forward}) {
        const glm::dvec3 rayStart = start.pointKm + start.distanceKm * (d - start.forward);
        const glm::dvec3 onTheRay = camera + start.distanceKm * d;
        EXPECT_LE(glm::length(rayStart - onTheRay), 1e-15 * 4.0 * distance);
        EXPECT_GE(glm::length(rayStart), 2.0 * reach * (1.0 - 1e-9));
    }
}
