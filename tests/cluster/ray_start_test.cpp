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

TEST(RayStart, AFarCamerasRaysStartBeyondTheSceneAndBeforeIt)
{
    const double reach = 6671.0;
    const glm::dvec3 camera(3e7, -9e7, 2e7);
    const glm::dvec3 forward = glm::normalize(-camera + glm::dvec3(0.0, 0.0, 6000.0));
    const cluster::RayStart start = cluster::rayStart(lookingFrom(camera, forward), reach);
    EXPECT_DOUBLE_EQ(start.distanceKm, glm::length(camera) - 2.0 * reach);
    EXPECT_NEAR(glm::length(start.pointKm - (camera + start.distanceKm * forward)), 0.0, 1e-8 * glm::length(camera));
    // Whatever the direction, a ray's start lies at least 2 reach from the centre (so it has passed
    // nothing) and its own start distance from the camera.
    for (const glm::dvec3 d : {forward, glm::normalize(forward + glm::dvec3(1e-4, 0.0, 0.0)),
                               glm::dvec3(1.0, 0.0, 0.0), -forward}) {
        const glm::dvec3 rayStart = camera + start.distanceKm * d;
        EXPECT_GE(glm::length(rayStart), 2.0 * reach * (1.0 - 1e-12));
    }
}
