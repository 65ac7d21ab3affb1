// Flying the camera from the windows (app/navigation.h): each key's effect in the camera's own axes
// against exact double arithmetic, the altitude-scaled speed, the ground clamp, and rotations that
// compose without NaN or loss of orthonormality.
#include "app/control/geographic_camera.h"
#include "app/navigation.h"
#include "physics/constants.h"
#include "gl/context.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace aurorawall::app {
namespace {

constexpr double kR = 6371.0;

cluster::InputEvent key(std::int32_t code) { return {gl::InputEvent::KeyPressed, code, 0.0, 0.0}; }
cluster::InputEvent drag(double dx, double dy) { return {gl::InputEvent::Dragged, 0, dx, dy}; }

scene::Camera cameraAt(double altitudeKm, double headingDeg = 30.0, double pitchDeg = 10.0)
{
    return control::cameraAt({65.0, 25.0, altitudeKm, headingDeg, pitchDeg}, kR, 0.0);
}

double altitude(const scene::Camera& c) { return glm::length(c.positionKm) - kR; }
glm::dvec3 rightOf(const scene::Camera& c) { return glm::cross(c.forward, c.up); }

// The position moved by one nudge along `axis` (a unit vector of the planet frame).
void expectMoved(const scene::Camera& from, const scene::Camera& to, const glm::dvec3& axis, double km)
{
    const glm::dvec3 d = to.positionKm - from.positionKm;
    // 1e-9 km: rounding of positions of ~6500 km (ulp 1e-12 km) through a few products.
    EXPECT_NEAR(glm::length(d - axis * km), 0.0, 1e-9);
}

TEST(Navigation, EachMoveKeyNudgesAlongTheCameraAxes)
{
    const scene::Camera c = cameraAt(100.0);
    const double nudgeKm = 100.0 * Navigation::kNudgeS; // 1 /s x 100 km x 0.1 s
    Navigation nav(kR);
    expectMoved(c, nav.apply(c, {key('W')}), c.forward, nudgeKm);
    expectMoved(c, nav.apply(c, {key('S')}), -c.forward, nudgeKm);
    expectMoved(c, nav.apply(c, {key('D')}), rightOf(c), nudgeKm);
    expectMoved(c, nav.apply(c, {key('A')}), -rightOf(c), nudgeKm);
    expectMoved(c, nav.apply(c, {key('R')}), c.up, nudgeKm);
    expectMoved(c, nav.apply(c, {key('F')}), -c.up, nudgeKm);
    // Moving keeps the view; the second nudge starts from the new altitude.
    const scene::Camera once = nav.apply(c, {key('W')});
    EXPECT_NEAR(glm::length(once.forward - c.forward), 0.0, 1e-15);
    expectMoved(once, nav.apply(c, {key('W'), key('W')}), c.forward, altitude(once) * Navigation::kNudgeS);
}

TEST(Navigation, UnknownKeysAndEventsChangeNothing)
{
    const scene::Camera c = cameraAt(100.0);
    Navigation nav(kR);
    const scene::Camera same = nav.apply(c, {key('Z'), key(0), {7, 'W', 0.0, 0.0}});
    EXPECT_EQ(same.positionKm, c.positionKm);
    EXPECT_NEAR(glm::length(same.forward - c.forward), 0.0, 1e-15);
    EXPECT_NEAR(glm::length(same.up - c.up), 0.0, 1e-15);
    EXPECT_EQ(nav.speedPerS(), 1.0);
}

TEST(Navigation, SpeedScalesWithAltitudeFromTheGroundToGeostationaryOrbit)
{
    Navigation nav(kR);
    EXPECT_DOUBLE_EQ(nav.speedKmPerS(0.0), 0.01);      // 10 m/s on the ground
    EXPECT_DOUBLE_EQ(nav.speedKmPerS(0.005), 0.01);    // and below 10 m
    EXPECT_DOUBLE_EQ(nav.speedKmPerS(2.0), 2.0);
    EXPECT_DOUBLE_EQ(nav.speedKmPerS(35786.0), 35786.0); // geostationary: 35786 km/s
    const scene::Camera geo = cameraAt(35786.0);
    expectMoved(geo, nav.apply(geo, {key('W')}), geo.forward, 3578.6);
    const scene::Camera ground = cameraAt(0.002, 0.0, 0.0);
    expectMoved(ground, nav.apply(ground, {key('W')}), ground.forward, 0.001); // 1 m per nudge

    // + doubles, - halves, within [1/1024, 8] /s.
    nav.apply(geo, {key(gl::KeyPlus)});
    EXPECT_EQ(nav.speedPerS(), 2.0);
    expectMoved(geo, nav.apply(geo, {key('S')}), -geo.forward, 2 * 3578.6);
    nav.apply(geo, std::vector<cluster::InputEvent>(10, key(gl::KeyPlus)));
    EXPECT_EQ(nav.speedPerS(), Navigation::kMaxSpeedPerS);
    nav.apply(geo, std::vector<cluster::InputEvent>(20, key(gl::KeyMinus)));
    EXPECT_EQ(nav.speedPerS(), Navigation::kMinSpeedPerS);
}

TEST(Navigation, NeverBelowTheGround)
{
    // Looking straight down from 500 m, at the fastest speed.
    const scene::Camera c = cameraAt(0.5, 0.0, -90.0);
    Navigation nav(kR);
    nav.apply(c, std::vector<cluster::InputEvent>(10, key(gl::KeyPlus)));
    scene::Camera now = c;
    for (int i = 0; i < 100; ++i) {
        now = nav.apply(now, {key('W')});
        ASSERT_GE(altitude(now), Navigation::kMinAltitudeKm - 1e-9) << "nudge " << i;
    }
    EXPECT_NEAR(altitude(now), Navigation::kMinAltitudeKm, 1e-9);
    // Still above the same point: the clamp moved the camera up, not sideways.
    EXPECT_NEAR(glm::length(glm::normalize(now.positionKm) - glm::normalize(c.positionKm)), 0.0, 1e-12);
}

TEST(Navigation, LookAndRollTurnAboutTheCameraAxes)
{
    const scene::Camera c = cameraAt(100.0);
    const glm::dvec3 right = rightOf(c);
    const double cos2 = std::cos(2 * aurorawall::physics::kDegree), sin2 = std::sin(2 * aurorawall::physics::kDegree);
    Navigation nav(kR);
    const scene::Camera r = nav.apply(c, {key(gl::KeyRight)});
    EXPECT_NEAR(glm::dot(r.forward, c.forward), cos2, 1e-14);
    EXPECT_NEAR(glm::dot(r.forward, right), sin2, 1e-14);
    EXPECT_NEAR(glm::dot(r.up, c.up), 1.0, 1e-14);
    const scene::Camera l = nav.apply(c, {key(gl::KeyLeft)});
    EXPECT_NEAR(glm::dot(l.forward, right), -sin2, 1e-14);
    const scene::Camera u = nav.apply(c, {key(gl::KeyUp)});
    EXPECT_NEAR(glm::dot(u.forward, c.up), sin2, 1e-14);
    EXPECT_NEAR(glm::dot(u.up, c.forward), -sin2, 1e-14);
    const scene::Camera d = nav.apply(c, {key(gl::KeyDown)});
    EXPECT_NEAR(glm::dot(d.forward, c.up), -sin2, 1e-14);
    const scene::Camera e = nav.apply(c, {key('E')}); // roll right: up leans to the right
    EXPECT_NEAR(glm::dot(e.up, right), sin2, 1e-14);
    EXPECT_NEAR(glm::dot(e.forward, c.forward), 1.0, 1e-14);
    const scene::Camera q = nav.apply(c, {key('Q')});
    EXPECT_NEAR(glm::dot(q.up, right), -sin2, 1e-14);
    EXPECT_EQ(e.positionKm, c.positionKm);
    // A drag of 10 px right and 10 px up turns as Right then Up (0.2 degrees per pixel).
    const scene::Camera dragged = nav.apply(c, {drag(10.0, -10.0)});
    const scene::Camera keyed = nav.apply(c, {key(gl::KeyRight), key(gl::KeyUp)});
    EXPECT_NEAR(glm::length(dragged.forward - keyed.forward), 0.0, 1e-14);
    EXPECT_NEAR(glm::length(dragged.up - keyed.up), 0.0, 1e-14);
    // 180 turns of 2 degrees come back to the start.
    const scene::Camera around = nav.apply(c, std::vector<cluster::InputEvent>(180, key(gl::KeyRight)));
    EXPECT_NEAR(glm::length(around.forward - c.forward), 0.0, 1e-12);
    EXPECT_NEAR(glm::length(around.up - c.up), 0.0, 1e-12);
}

TEST(Navigation, ManyEventsStayFiniteAndOrthonormal)
{
    std::mt19937 random(7);
    const std::int32_t keys[] = {'W', 'S', 'A', 'D', 'R', 'F', 'Q', 'E', gl::KeyUp, gl::KeyDown,
                                 gl::KeyLeft, gl::KeyRight, gl::KeyPlus, gl::KeyMinus};
    std::uniform_int_distribution<int> pick(0, 14); // 14: a drag
    std::uniform_real_distribution<double> pixels(-300.0, 300.0);
    Navigation nav(kR);
    scene::Camera c = cameraAt(100.0);
    // 20000 frames of 5 events, each frame starting from the last one's camera as the wall does.
    for (int frame = 0; frame < 20000; ++frame) {
        std::vector<cluster::InputEvent> events;
        for (int i = 0; i < 5; ++i) {
            const int k = pick(random);
            events.push_back(k == 14 ? drag(pixels(random), pixels(random)) : key(keys[k]));
        }
        c = nav.apply(c, events);
        ASSERT_TRUE(std::isfinite(c.positionKm.x + c.positionKm.y + c.positionKm.z)) << "frame " << frame;
        ASSERT_GE(altitude(c), Navigation::kMinAltitudeKm - 1e-9) << "frame " << frame;
        // 1e-13: a few ulps of unit vectors, with no growth over the frames.
        ASSERT_NEAR(glm::length(c.forward), 1.0, 1e-13) << "frame " << frame;
        ASSERT_NEAR(glm::length(c.up), 1.0, 1e-13) << "frame " << frame;
        ASSERT_NEAR(glm::dot(c.forward, c.up), 0.0, 1e-13) << "frame " << frame;
    }
}

} // namespace
} // namespace aurorawall::app
