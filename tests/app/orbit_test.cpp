// Orbiting a point (control/orbit.h, app/navigation.h's O key): the pivot where the view axis meets the
// ground, the pivot at the centre of the view and at the same distance through a full circle and over
// its zenith (without a flip of the view), the ground clamp of turns and of W, and the distance speed.
#include "app/control/geographic_camera.h"
#include "app/control/orbit.h"
#include "app/navigation.h"
#include "physics/constants.h"
#include "gl/context.h"

#include <gtest/gtest.h>

#include <cmath>

namespace aurorawall::app {
namespace {

constexpr double kR = 6371.0;
constexpr double kMinRadiusKm = kR + Navigation::kMinAltitudeKm;

cluster::InputEvent key(std::int32_t code) { return {gl::InputEvent::KeyPressed, code, 0.0, 0.0}; }
cluster::InputEvent drag(double dx, double dy) { return {gl::InputEvent::Dragged, 0, dx, dy}; }

scene::Camera cameraAt(double altitudeKm, double headingDeg, double pitchDeg)
{
    return control::cameraAt({65.0, 25.0, altitudeKm, headingDeg, pitchDeg}, kR, 3.0);
}

double altitude(const scene::Camera& c) { return glm::length(c.positionKm) - kR; }
glm::dvec3 rightOf(const scene::Camera& c) { return glm::cross(c.forward, c.up); }
double angleDeg(const glm::dvec3& a, const glm::dvec3& b)
{
    return std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b)) / aurorawall::physics::kDegree;
}

// The pivot is at the centre of the view (1e-9 relative: rounding of ~6400 km positions through a few
// hundred rotations is ~1e-13) at `distanceKm`.
void expectCentred(const scene::Camera& c, const glm::dvec3& pivot, double distanceKm, const std::string& where)
{
    const glm::dvec3 toPivot = pivot - c.positionKm;
    EXPECT_NEAR(glm::length(toPivot) / distanceKm, 1.0, 1e-9) << where;
    EXPECT_NEAR(glm::length(glm::cross(glm::normalize(toPivot), c.forward)), 0.0, 1e-9) << where;
    EXPECT_GT(glm::dot(toPivot, c.forward), 0.0) << where;
    EXPECT_NEAR(glm::dot(c.forward, c.up), 0.0, 1e-12) << where;
}

// The camera orbiting from `c` with the O key, and its pivot.
std::pair<scene::Camera, glm::dvec3> startOrbit(Navigation& nav, const scene::Camera& c)
{
    const scene::Camera orbiting = nav.apply(c, {key('O')});
    EXPECT_TRUE(nav.pivot().has_value());
    return {orbiting, nav.pivot().value_or(glm::dvec3(0.0))};
}

TEST(Orbit, PivotIsWhereTheViewAxisMeetsTheGround)
{
    // 10 km up looking 30 degrees down: the first root of |p + t f| = R, in long double.
    const scene::Camera c = cameraAt(10.0, 40.0, -30.0);
    const glm::dvec3 pivot = control::orbitPivot(c, kR);
    const long double b = glm::dot(c.positionKm, c.forward);
    const long double cc = (long double)glm::dot(c.positionKm, c.positionKm) - (long double)kR * kR;
    const long double t = -b - std::sqrt(b * b - cc);
    EXPECT_NEAR(glm::length(pivot), kR, 1e-9);
    EXPECT_NEAR(glm::length(pivot - c.positionKm), (double)t, 1e-9);
    EXPECT_NEAR(glm::length(glm::cross(glm::normalize(pivot - c.positionKm), c.forward)), 0.0, 1e-12);
    // Looking 10 degrees up from 400 km the axis misses: the point as far along it as the centre is.
    const scene::Camera up = cameraAt(400.0, 0.0, 10.0);
    const glm::dvec3 far = control::orbitPivot(up, kR);
    EXPECT_NEAR(glm::length(far - up.positionKm), kR + 400.0, 1e-9);
    EXPECT_NEAR(glm::length(glm::cross(glm::normalize(far - up.positionKm), up.forward)), 0.0, 1e-12);
}

TEST(Orbit, OKeyStartsAtTheGroundPointHoldsStillAndTogglesBack)
{
    const scene::Camera c = cameraAt(10.0, 40.0, -30.0);
    Navigation nav(kR);
    const auto [orbiting, pivot] = startOrbit(nav, c);
    EXPECT_NEAR(glm::length(pivot - control::orbitPivot(c, kR)), 0.0, 1e-12);
    EXPECT_EQ(orbiting.positionKm, c.positionKm);
    EXPECT_EQ(orbiting.speedKmPerS, 0.0);
    // O again: free flight, where Right turns the view in place.
    const scene::Camera free = nav.apply(orbiting, {key('O'), key(gl::KeyRight)});
    EXPECT_FALSE(nav.pivot().has_value());
    EXPECT_EQ(free.positionKm, c.positionKm);
    EXPECT_NEAR(angleDeg(free.forward, c.forward), 2.0, 1e-9);
}

TEST(Orbit, FullCircleKeepsThePivotCentredAtTheSameDistanceAndAltitude)
{
    const scene::Camera c = cameraAt(10.0, 40.0, -30.0);
    Navigation nav(kR);
    auto [now, pivot] = startOrbit(nav, c);
    const double distanceKm = glm::length(pivot - c.positionKm);
    for (int i = 1; i <= 180; ++i) {
        const scene::Camera before = now;
        now = nav.apply(now, {key(gl::KeyRight)});
        expectCentred(now, pivot, distanceKm, "step " + std::to_string(i));
        // About the pivot's zenith (through the planet's centre): the altitude stays.
        ASSERT_NEAR(altitude(now), 10.0, 1e-9) << "step " << i;
        ASSERT_GT(glm::dot(now.positionKm - before.positionKm, rightOf(before)), 0.0) << "Right goes right";
    }
    EXPECT_NEAR(glm::length(now.positionKm - c.positionKm) / distanceKm, 0.0, 1e-9);
    EXPECT_NEAR(glm::length(now.up - c.up), 0.0, 1e-9);
}

TEST(Orbit, PassingOverThePivotsZenithDoesNotFlip)
{
    const scene::Camera c = cameraAt(10.0, 0.0, -45.0); // south of the pivot, looking north
    Navigation nav(kR);
    auto [now, pivot] = startOrbit(nav, c);
    const double distanceKm = glm::length(pivot - c.positionKm);
    const glm::dvec3 zenith = glm::normalize(pivot);
    const glm::dvec3 north = glm::normalize(glm::cross(glm::cross(zenith, c.forward), zenith));
    // The camera's angle over the pivot's horizon, counted from the south side across the zenith.
    const auto unfolded = [&](const scene::Camera& cam) {
        const glm::dvec3 d = glm::normalize(cam.positionKm - pivot);
        return std::atan2(glm::dot(d, zenith), -glm::dot(d, north)) / aurorawall::physics::kDegree;
    };
    const double start = unfolded(now);
    for (int i = 1; i <= 60; ++i) { // 120 degrees: from ~45 over the zenith to ~15 on the north side
        const scene::Camera before = now;
        now = nav.apply(now, {key(gl::KeyUp)});
        const std::string where = "step " + std::to_string(i);
        expectCentred(now, pivot, distanceKm, where);
        EXPECT_NEAR(unfolded(now), start + 2.0 * i, 1e-9) << where;
        // Each press turns the view and its up by 2 degrees, never by 180.
        EXPECT_NEAR(angleDeg(now.forward, before.forward), 2.0, 1e-9) << where;
        EXPECT_NEAR(angleDeg(now.up, before.up), 2.0, 1e-9) << where;
    }
    EXPECT_GT(glm::dot(now.positionKm - pivot, north), 0.0) << "now north of the pivot";
    EXPECT_LT(glm::dot(now.up, zenith), 0.0) << "upside down past the top, not flipped";
    // Upside down, Right still carries the camera to its own right.
    const scene::Camera right = nav.apply(now, {key(gl::KeyRight)});
    EXPECT_GT(glm::dot(right.positionKm - now.positionKm, rightOf(now)), 0.0);
    expectCentred(right, pivot, distanceKm, "right after the top");
}

TEST(Orbit, DragTurnsTheSceneWithThePointer)
{
    const scene::Camera c = cameraAt(10.0, 40.0, -30.0);
    Navigation nav(kR);
    const scene::Camera orbiting = startOrbit(nav, c).first;
    // 10 px right: the camera goes left 2 degrees; 10 px up: it goes down 2 degrees.
    const scene::Camera dragged = nav.apply(orbiting, {drag(10.0, 0.0), drag(0.0, -10.0)});
    const scene::Camera keyed = nav.apply(orbiting, {key(gl::KeyLeft), key(gl::KeyDown)});
    EXPECT_NEAR(glm::length(dragged.positionKm - keyed.positionKm), 0.0, 1e-9);
    EXPECT_NEAR(glm::length(dragged.up - keyed.up), 0.0, 1e-12);
}

TEST(Orbit, TurnsStopAtTheGround)
{
    const scene::Camera c = cameraAt(10.0, 40.0, -30.0);
    Navigation nav(kR);
    auto [now, pivot] = startOrbit(nav, c);
    const double distanceKm = glm::length(pivot - c.positionKm);
    const glm::dvec3 zenith = glm::normalize(pivot);
    for (int i = 0; i < 100; ++i) {
        now = nav.apply(now, {key(gl::KeyDown)});
        ASSERT_GE(altitude(now), Navigation::kMinAltitudeKm) << "press " << i;
        expectCentred(now, pivot, distanceKm, "press " + std::to_string(i));
    }
    // It stopped within one 2-degree turn of where it would pass below 1 m.
    const double elevationDeg = std::asin(glm::dot(glm::normalize(now.positionKm - pivot), zenith)) / aurorawall::physics::kDegree;
    EXPECT_LT(elevationDeg, 2.0);
    EXPECT_LT(altitude(control::orbitTurned(now, pivot, 0.0, -2.0, 0.0)), Navigation::kMinAltitudeKm);
}

TEST(Orbit, WAndSScaleWithTheDistanceAndWStopsAtTheGround)
{
    const scene::Camera c = cameraAt(10.0, 40.0, -30.0);
    Navigation nav(kR);
    auto [now, pivot] = startOrbit(nav, c);
    const double distanceKm = glm::length(pivot - c.positionKm);
    // One press: 0.1 s at 1 x the distance per second.
    const scene::Camera away = nav.apply(now, {key('S')});
    expectCentred(away, pivot, distanceKm * 1.1, "S");
    const scene::Camera toward = nav.apply(now, {key('W')});
    expectCentred(toward, pivot, distanceKm * 0.9, "W");
    // At 8 /s each press takes 0.8 of the distance; the camera ends 1 m above the ground on the axis.
    nav.apply(now, std::vector<cluster::InputEvent>(10, key(gl::KeyPlus)));
    for (int i = 0; i < 100; ++i) {
        now = nav.apply(now, {key('W')});
        ASSERT_GE(altitude(now), Navigation::kMinAltitudeKm - 1e-9) << "press " << i;
    }
    EXPECT_NEAR(altitude(now), Navigation::kMinAltitudeKm, 1e-9);
    const glm::dvec3 toPivot = pivot - now.positionKm;
    EXPECT_NEAR(glm::length(glm::cross(glm::normalize(toPivot), c.forward)), 0.0, 1e-9);
}

TEST(Orbit, AimedAtLooksAtThePointWithALevelHorizon)
{
    const scene::Camera c = cameraAt(10.0, 40.0, -30.0);
    const glm::dvec3 pivot = scene::planetPoint(66.0, 20.0, kR);
    const scene::Camera aimed = control::aimedAt(c, pivot);
    expectCentred(aimed, pivot, glm::length(pivot - c.positionKm), "aimed");
    EXPECT_NEAR(glm::dot(rightOf(aimed), glm::normalize(c.positionKm)), 0.0, 1e-12); // level
    EXPECT_GT(glm::dot(aimed.up, glm::normalize(c.positionKm)), 0.0);
    EXPECT_EQ(aimed.speedKmPerS, 0.0);
    // Straight below: up is the present up made perpendicular.
    const scene::Camera down = control::aimedAt(c, c.positionKm * (kR / glm::length(c.positionKm)));
    EXPECT_NEAR(glm::length(down.forward + glm::normalize(c.positionKm)), 0.0, 1e-12);
    EXPECT_NEAR(glm::dot(down.up, down.forward), 0.0, 1e-12);
    EXPECT_NEAR(glm::length(down.up), 1.0, 1e-12);
}

} // namespace
} // namespace aurorawall::app
