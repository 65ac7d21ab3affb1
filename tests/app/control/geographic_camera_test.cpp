// The camera in latitude, longitude, altitude, heading and pitch: known directions of the planet
// frame (z north, x toward longitude 180 deg, y toward 90 deg W), and the round trip.
#include "app/control/geographic_camera.h"

#include <gtest/gtest.h>

using namespace aurorawall;
using namespace aurorawall::app::control;

namespace {

constexpr double kRadiusKm = 6371.0;

void expectNear(const glm::dvec3& a, const glm::dvec3& b, double tolerance)
{
    EXPECT_NEAR(a.x, b.x, tolerance);
    EXPECT_NEAR(a.y, b.y, tolerance);
    EXPECT_NEAR(a.z, b.z, tolerance);
}

} // namespace

TEST(GeographicCamera, KnownDirectionsAtTheEquator)
{
    // At latitude 0, longitude 0 the zenith is -x, north is +z and east (toward 90 deg E) is -y.
    GeographicPose pose{0.0, 0.0, 100.0, 90.0, 0.0};
    scene::Camera east = cameraAt(pose, kRadiusKm, 3.0);
    expectNear(east.positionKm, {-(kRadiusKm + 100.0), 0.0, 0.0}, 1e-9);
    expectNear(east.forward, {0.0, -1.0, 0.0}, 1e-15);
    expectNear(east.up, {-1.0, 0.0, 0.0}, 1e-15);
    EXPECT_EQ(east.speedKmPerS, 3.0);
    pose.headingDeg = 0.0;
    pose.pitchDeg = 30.0; // north, 30 deg up: (cos 30) north + (sin 30) zenith
    expectNear(cameraAt(pose, kRadiusKm, 0.0).forward, {-0.5, 0.0, std::sqrt(3.0) / 2}, 1e-15);
    pose.pitchDeg = 90.0; // the zenith; up is then the heading's direction reversed (as in scene files)
    const scene::Camera zenith = cameraAt(pose, kRadiusKm, 0.0);
    expectNear(zenith.forward, {-1.0, 0.0, 0.0}, 1e-15);
    expectNear(zenith.up, {0.0, 0.0, -1.0}, 1e-15);
}

TEST(GeographicCamera, PoseRoundTrips)
{
    const GeographicPose poses[] = {{65.0, 25.0, 200.0, 299.0, 10.4},
                                    {-59.2, -170.5, 0.07, 0.0, -45.0},
                                    {12.0, 179.0, 35786.0, 180.0, 0.0},
                                    {-89.0, 0.5, 1.0, 90.0, 89.0}};
    for (const GeographicPose& p : poses) {
        const GeographicPose q = poseOf(cameraAt(p, kRadiusKm, 0.0), kRadiusKm);
        EXPECT_NEAR(q.latitudeDeg, p.latitudeDeg, 1e-9);
        EXPECT_NEAR(q.longitudeDeg, p.longitudeDeg, 1e-9);
        // 1e-8 km: a few ulps of a distance of 6400 to 42000 km.
        EXPECT_NEAR(q.altitudeKm, p.altitudeKm, 1e-8);
        EXPECT_NEAR(q.headingDeg, p.headingDeg, 1e-7); // near the zenith heading is ill-conditioned
        EXPECT_NEAR(q.pitchDeg, p.pitchDeg, 1e-9);
        const scene::Camera c = cameraAt(p, kRadiusKm, 0.0);
        EXPECT_NEAR(glm::dot(c.forward, c.up), 0.0, 1e-15);
        EXPECT_NEAR(glm::length(c.up), 1.0, 1e-15);
    }
}

TEST(GeographicCamera, TheBenchmarkCameraIsOverSouthernFinland)
{
    // The published benchmark view: C = (-0.467287, -0.223999, 0.868115) planet radii, about 70 km
    // up at 59.2 N 25.6 E, heading 299 deg, 10.4 deg above the horizontal.
    scene::Camera c;
    c.positionKm = glm::dvec3(-0.467287, -0.223999, 0.868115) * kRadiusKm;
    c.forward = glm::normalize(glm::dvec3(-0.083353, 0.912453, 0.400601));
    const GeographicPose p = poseOf(c, kRadiusKm);
    EXPECT_NEAR(p.latitudeDeg, 59.2, 0.05);
    EXPECT_NEAR(p.longitudeDeg, 25.6, 0.05);
    EXPECT_NEAR(p.altitudeKm, 0.011017 * kRadiusKm, 0.01);
    EXPECT_NEAR(p.headingDeg, 299.0, 0.5);
    EXPECT_NEAR(p.pitchDeg, 10.4, 0.1);
}
