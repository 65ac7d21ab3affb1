// Keyed camera paths: C1 positions and orientations (against slerp's and Shoemake's even-spacing
// SQUAD's kinks), orientations without flips, exact at the keys, held outside them, independent of
// the frame step; the benchmark flight as a path; errors naming file:line:key.
#include "physics/constants.h"
#include "cluster/master_clock.h"
#include "common/input_error.h"
#include "components/registry.h"
#include "scene/camera_path.h"
#include "scene/scene.h"
#include "load_error.h"

#include <gtest/gtest.h>

#define GLM_ENABLE_EXPERIMENTAL // glm::squad and glm::intermediate, Shoemake's SQUAD as glm writes it
#include <glm/gtx/quaternion.hpp>

#include <algorithm>
#include <cmath>
#include <functional>
#include <string>

using namespace aurorawall;
using scene::CameraFrame, scene::CameraKey, scene::CameraPath;

namespace {

const std::string kData = SCENE_TEST_DATA;
const std::string kScenes = SCENE_CONFIG_DIR;

// The rotation angle between two orientations (radians; q and -q are the same rotation).
double angleBetween(const glm::dquat& a, const glm::dquat& b)
{
    return 2.0 * std::acos(std::min(1.0, std::abs(glm::dot(a, b))));
}

// A frame turned by `angle` about the planet's z axis from looking along +y, tilted so that both
// forward and up change.
CameraFrame turned(double angle)
{
    const glm::dvec3 forward{-std::sin(angle), std::cos(angle), 0.3};
    const glm::dvec3 up = glm::normalize(glm::dvec3(0.2 * std::cos(angle), 0.2 * std::sin(angle), 1.0));
    CameraFrame f;
    f.forward = glm::normalize(forward);
    f.up = glm::normalize(up - f.forward * glm::dot(up, f.forward));
    return f;
}

// Five keys at uneven times along a curve 70-250 km up, turning 60 deg per key.
std::vector<CameraKey> curvedKeys()
{
    const double times[] = {0.0, 4.0, 5.5, 12.0, 13.0};
    const glm::dvec3 positions[] = {
        {0.0, 0.0, 6441.0}, {30.0, 80.0, 6450.0}, {70.0, 95.0, 6480.0}, {40.0, 200.0, 6520.0}, {45.0, 230.0, 6600.0}};
    std::vector<CameraKey> keys;
    for (int i = 0; i < 5; ++i)
        keys.push_back({times[i], positions[i], scene::orientationOf(turned(i * aurorawall::physics::kPi / 3.0))});
    return keys;
}

// The angular velocity (rad/s, planet frame) at t from one side: w = 2 vec(dq/dt q*), with dq/dt
// the second-order one-sided difference of step `step` (negative: from before t).
glm::dvec3 angularVelocity(const std::function<glm::dquat(double)>& q, double t, double step)
{
    const glm::dquat rate = (-3.0 * q(t) + 4.0 * q(t + step) - q(t + 2.0 * step)) * (1.0 / (2.0 * step));
    const glm::dquat w = rate * glm::conjugate(q(t));
    return 2.0 * glm::dvec3(w.x, w.y, w.z);
}

// Slerp between consecutive keys (already in one hemisphere), which turns at a constant rate within
// each segment and so changes its angular velocity abruptly at every key.
glm::dquat piecewiseSlerp(const std::vector<CameraKey>& keys, double t)
{
    std::size_t i = 0;
    while (i + 2 < keys.size() && t >= keys[i + 1].timeS)
        ++i;
    const double s = std::clamp((t - keys[i].timeS) / (keys[i + 1].timeS - keys[i].timeS), 0.0, 1.0);
    return glm::slerp(keys[i].orientation, keys[i + 1].orientation, s);
}

// Shoemake's SQUAD (1987) by glm, with his control points s_i = q_i exp(-(log(q_i* q_{i+1}) +
// log(q_i* q_{i-1})) / 4), which assume evenly spaced keys; s = q at the end keys.
glm::dquat shoemakeSquad(const std::vector<CameraKey>& keys, double t)
{
    std::size_t i = 0;
    while (i + 2 < keys.size() && t >= keys[i + 1].timeS)
        ++i;
    const auto control = [&](std::size_t k) {
        return k == 0 || k + 1 == keys.size()
                   ? keys[k].orientation
                   : glm::intermediate(keys[k - 1].orientation, keys[k].orientation, keys[k + 1].orientation);
    };
    const double s = (t - keys[i].timeS) / (keys[i + 1].timeS - keys[i].timeS);
    return glm::squad(keys[i].orientation, keys[i + 1].orientation, control(i), control(i + 1), s);
}

using aurorawall::test::loadError;

} // namespace

TEST(CameraPath, ExactAtTheKeys)
{
    const std::vector<CameraKey> keys = curvedKeys();
    const CameraPath path(keys);
    for (std::size_t i = 0; i < keys.size(); ++i) {
        EXPECT_EQ(path.positionAt(keys[i].timeS), keys[i].positionKm) << "key " << i;
        const CameraFrame want = turned(static_cast<double>(i) * aurorawall::physics::kPi / 3.0);
        const CameraFrame got = scene::frameOf(path.orientationAt(keys[i].timeS));
        EXPECT_NEAR(glm::length(got.forward - want.forward), 0.0, 1e-14) << "key " << i;
        EXPECT_NEAR(glm::length(got.up - want.up), 0.0, 1e-14) << "key " << i;
        EXPECT_EQ(path.orientationAt(keys[i].timeS), path.keys()[i].orientation) << "key " << i;
    }
}

TEST(CameraPath, PositionAndVelocityAreContinuousAtTheKeys)
{
    const std::vector<CameraKey> keys = curvedKeys();
    const CameraPath path(keys);
    // Second-order one-sided differences from each side of a key, (3 p(t) - 4 p(t - eps) + p(t - 2 eps))
    // / 2 eps and its mirror: off the derivative by |third derivative| eps^2 / 3 (measured: at most
    // 1.3e-6 km/s at eps = 1e-4 s), rounding adds about 4e-12 km / eps. A path only C0 at the keys
    // (straight segments) jumps in velocity by the change of chord slope, above 10 km/s on these keys.
    const double eps = 1e-4;
    for (std::size_t i = 1; i + 1 < keys.size(); ++i) {
        const double t = keys[i].timeS;
        const glm::dvec3 p = path.positionAt(t);
        EXPECT_LT(glm::length(path.positionAt(t - eps) - p), 1e-2) << "key " << i;
        EXPECT_LT(glm::length(path.positionAt(t + eps) - p), 1e-2) << "key " << i;
        const glm::dvec3 before = (3.0 * p - 4.0 * path.positionAt(t - eps) + path.positionAt(t - 2 * eps)) / (2 * eps);
        const glm::dvec3 after = (-3.0 * p + 4.0 * path.positionAt(t + eps) - path.positionAt(t + 2 * eps)) / (2 * eps);
        EXPECT_LT(glm::length(after - before), 1e-5) << "key " << i;
        // The velocity at a key is the centred difference of its neighbours.
        const glm::dvec3 tangent = (keys[i + 1].positionKm - keys[i - 1].positionKm) / (keys[i + 1].timeS - keys[i - 1].timeS);
        EXPECT_LT(glm::length(after - tangent), 1e-5) << "key " << i;
        const glm::dvec3 chordBefore = (keys[i].positionKm - keys[i - 1].positionKm) / (keys[i].timeS - keys[i - 1].timeS);
        const glm::dvec3 chordAfter = (keys[i + 1].positionKm - keys[i].positionKm) / (keys[i + 1].timeS - keys[i].timeS);
        EXPECT_GT(glm::length(chordAfter - chordBefore), 10.0) << "the test's keys must bend";
    }
}

TEST(CameraPath, AngularVelocityIsContinuousAtTheKeys)
{
    const CameraPath path(curvedKeys()); // uneven segments: 4, 1.5, 6.5 and 1 s
    const std::vector<CameraKey>& keys = path.keys();
    const auto squad = [&](double t) { return path.orientationAt(t); };
    const auto slerped = [&](double t) { return piecewiseSlerp(keys, t); };
    // The one-sided differences are off the derivative by |third derivative| eps^2 / 3: measured
    // jumps of 6.9e-7, 6.9e-9 and 6.1e-11 rad/s at steps of 1e-3, 1e-4 and 1e-5 s at key 1 (1.6e-6,
    // 1.6e-8, 1.9e-10 at key 3), falling as eps^2, so the spline itself does not jump. Slerp between
    // the same keys jumps by 0.44 to 0.89 rad/s.
    const double eps = 1e-4, tolerance = 1e-7;
    for (std::size_t i = 1; i + 1 < keys.size(); ++i) {
        const double t = keys[i].timeS;
        const glm::dvec3 before = angularVelocity(squad, t, -eps), after = angularVelocity(squad, t, eps);
        EXPECT_LT(glm::length(after - before), tolerance) << "key " << i;
        EXPECT_GT(glm::length(after), 0.2) << "key " << i << ": the camera turns there";
        const double slerpJump = glm::length(angularVelocity(slerped, t, eps) - angularVelocity(slerped, t, -eps));
        EXPECT_GT(slerpJump, 0.4) << "key " << i << ": the measure sees slerp's kink";
    }
}

// Keys at `times` turning by uneven steps (50, 80, 40, 90 deg), so that no key's Shoemake control
// point is the key itself (glm::exp gives the zero quaternion for a zero vector).
std::vector<CameraKey> unevenTurns(const std::vector<double>& times)
{
    const double degrees[] = {0.0, 50.0, 130.0, 170.0, 260.0};
    std::vector<CameraKey> keys;
    for (std::size_t i = 0; i < times.size(); ++i)
        keys.push_back({times[i], glm::dvec3(0.0), scene::orientationOf(turned(degrees[i] * aurorawall::physics::kPi / 180.0))});
    return keys;
}

TEST(CameraPath, EvenlySpacedKeysGiveShoemakesSquad)
{
    const CameraPath path(unevenTurns({0.0, 2.0, 4.0, 6.0, 8.0}));
    double largest = 0.0;
    for (double t = 0.0; t < 8.0; t += 1e-2)
        largest = std::max(largest, angleBetween(path.orientationAt(t), shoemakeSquad(path.keys(), t)));
    // glm's slerp takes the angle by acos, which resolves small angles only to about
    // sqrt(2 x 1.1e-16) = 1.5e-8 rad per blend (measured: 6.0e-8 rad at most); control points
    // different from Shoemake's would differ by the size of the turns (about 1e-2 rad and more).
    EXPECT_LT(largest, 1e-6);
}

TEST(CameraPath, ShoemakesControlPointsKinkAtUnevenKeys)
{
    // The control for the time weighting: on keys at uneven times, SQUAD with Shoemake's control
    // points jumps in angular velocity at the keys, this path does not.
    const CameraPath path(unevenTurns({0.0, 4.0, 5.5, 12.0, 13.0}));
    const std::vector<CameraKey>& keys = path.keys();
    const auto shoemake = [&](double t) { return shoemakeSquad(keys, t); };
    const auto squad = [&](double t) { return path.orientationAt(t); };
    // Measured: Shoemake's jumps 0.47, 0.54 and 0.96 rad/s, this path's 1.1e-8 to 2.6e-8 rad/s (the
    // differences' truncation at 1e-4 s, as in AngularVelocityIsContinuousAtTheKeys).
    for (std::size_t i = 1; i + 1 < keys.size(); ++i) {
        const double t = keys[i].timeS;
        const double jump = glm::length(angularVelocity(shoemake, t, 1e-4) - angularVelocity(shoemake, t, -1e-4));
        const double ours = glm::length(angularVelocity(squad, t, 1e-4) - angularVelocity(squad, t, -1e-4));
        EXPECT_GT(jump, 0.4) << "key " << i;
        EXPECT_LT(ours, 1e-7) << "key " << i;
    }
}

TEST(CameraPath, OrientationsStayUnitQuaternions)
{
    const CameraPath path(curvedKeys());
    double worst = 0.0;
    for (double t = -1.0; t < 14.0; t += 1e-3)
        worst = std::max(worst, std::abs(glm::length(path.orientationAt(t)) - 1.0));
    EXPECT_LT(worst, 4.0 * 2.2e-16); // measured 4.4e-16: a few roundings of the three slerps
}

TEST(CameraPath, NoOrientationFlipsEvenForKeysOfOppositeSign)
{
    std::vector<CameraKey> keys = curvedKeys();
    for (std::size_t i = 1; i < keys.size(); i += 2)
        keys[i].orientation = -keys[i].orientation; // the same rotations, quaternions of the other sign
    const CameraPath path(keys);
    // Samples dt apart stay in one hemisphere (no jump to -q) and turn by at most twice the fastest
    // key step, 60 deg in the 1 s segment, times dt: the spline's fastest turn is 1.24 times that
    // (measured); the long way round (300 deg) would be five times.
    const double dt = 1e-3, fastest = aurorawall::physics::kPi / 3.0;
    double largest = 0.0;
    glm::dquat last = path.orientationAt(-1.0);
    for (double t = -1.0 + dt; t < 14.0; t += dt) {
        const glm::dquat q = path.orientationAt(t);
        ASSERT_GT(glm::dot(last, q), 0.0) << "at " << t << " s";
        largest = std::max(largest, angleBetween(last, q));
        last = q;
    }
    EXPECT_LE(largest, 2.0 * fastest * dt);
    EXPECT_GT(largest, fastest * dt); // the measure sees the fastest segment
}

TEST(CameraPath, TurnsOfAlmostHalfAWayRoundGoTheShortWay)
{
    // Keys 179 deg apart about the planet's z axis at uneven times: the camera turns 358 deg one way
    // (never back), where the long way round for either step (181 deg the other way) would reverse it.
    const glm::dvec3 z(0.0, 0.0, 1.0);
    const double step = 179.0 * aurorawall::physics::kPi / 180.0;
    for (const double sign : {1.0, -1.0}) {
        const CameraPath path({{0.0, glm::dvec3(0.0), glm::angleAxis(0.0, z)},
                               {1.0, glm::dvec3(0.0), sign * glm::angleAxis(step, z)},
                               {3.5, glm::dvec3(0.0), glm::angleAxis(2.0 * step, z)}});
        const double dt = 1e-3;
        double turned = 0.0;
        glm::dquat last = path.orientationAt(0.0);
        for (double t = dt; t < 3.5 + dt / 2; t += dt) {
            const glm::dquat q = path.orientationAt(t);
            ASSERT_GT(glm::dot(last, q), 0.0) << "at " << t << " s";
            const glm::dquat turn = glm::conjugate(last) * q; // about z only: all keys share the axis
            ASSERT_GT(turn.z * turn.w, 0.0) << "at " << t << " s: the camera turns back";
            turned += angleBetween(last, q);
            last = q;
        }
        EXPECT_NEAR(turned, 2.0 * step, 1e-9);
        EXPECT_EQ(path.orientationAt(3.5), path.keys().back().orientation);
    }
}

TEST(CameraPath, HoldsStillBeforeTheFirstKeyAndAfterTheLast)
{
    const std::vector<CameraKey> keys = curvedKeys();
    const CameraPath path(keys);
    for (double t : {-1e6, -1.0, 0.0}) {
        EXPECT_EQ(path.positionAt(t), keys.front().positionKm);
        EXPECT_EQ(path.orientationAt(t), keys.front().orientation);
    }
    for (double t : {13.0, 14.0, 1e6}) {
        EXPECT_EQ(path.positionAt(t), keys.back().positionKm);
        EXPECT_EQ(angleBetween(path.orientationAt(t), keys.back().orientation), 0.0);
    }
}

TEST(CameraPath, PlaysTheSameAtAnyFrameStep)
{
    scene::Camera camera;
    camera.path = CameraPath(curvedKeys());
    cluster::ClockSettings at30, at7;
    at30.timeStepS = 1.0 / 30.0;
    at7.timeStepS = 1.0 / 7.0;
    at30.frames = at7.frames = 0;
    cluster::MasterClock clock30(at30, camera, 1.0), clock7(at7, camera, 1.0);
    // Whole seconds: frame 30 n of one clock and frame 7 n of the other show the same time (to the
    // rounding of n x dt) and so the same camera.
    for (int second = 0; second <= 14; ++second) {
        cluster::FrameState a = clock30.next(false), b = clock7.next(false);
        for (int n = 1; second > 0 && n < 30; ++n)
            a = clock30.next(false);
        for (int n = 1; second > 0 && n < 7; ++n)
            b = clock7.next(false);
        ASSERT_NEAR(a.timeS, second, 1e-12);
        ASSERT_NEAR(b.timeS, second, 1e-12);
        EXPECT_LT(glm::length(a.cameraPositionKm - b.cameraPositionKm), 1e-9) << second << " s";
        EXPECT_LT(glm::length(a.cameraBack - b.cameraBack), 1e-12) << second << " s";
        EXPECT_LT(glm::length(a.cameraUp - b.cameraUp), 1e-12) << second << " s";
        EXPECT_EQ(a.cameraPositionKm, camera.path.positionAt(a.timeS));
    }
}

TEST(CameraPath, TheBenchmarkPathIsTheStraightBenchmarkFlight)
{
    const scene::Scene straight = components::loadScene(kScenes + "/benchmark-view.toml");
    const scene::Scene keyed = components::loadScene(kScenes + "/benchmark-path.toml");
    ASSERT_TRUE(straight.camera.path.empty());
    ASSERT_EQ(keyed.camera.path.keys().size(), 2u);
    cluster::ClockSettings settings;
    settings.startTimeS = straight.startTimeS;
    settings.timeStepS = straight.timeStepS;
    settings.frames = 61;
    ASSERT_EQ(keyed.startTimeS, settings.startTimeS);
    ASSERT_EQ(keyed.timeStepS, settings.timeStepS);
    cluster::MasterClock a(settings, straight.camera, 1.0), b(settings, keyed.camera, 1.0);
    double largest = 0.0;
    for (int frame = 0; frame < 61; ++frame) {
        const cluster::FrameState s = a.next(false), k = b.next(false);
        ASSERT_EQ(s.timeS, k.timeS);
        largest = std::max(largest, glm::length(s.cameraPositionKm - k.cameraPositionKm));
        EXPECT_LT(glm::length(s.cameraBack - k.cameraBack), 1e-12) << "frame " << frame;
        EXPECT_LT(glm::length(s.cameraUp - k.cameraUp), 1e-12) << "frame " << frame;
        EXPECT_LT(glm::length(s.cameraRight - k.cameraRight), 1e-12) << "frame " << frame;
        // Both keys look the same way: the spline keeps that orientation bit for bit in between.
        EXPECT_EQ(keyed.camera.path.orientationAt(k.timeS), keyed.camera.path.keys()[0].orientation)
            << "frame " << frame;
    }
    EXPECT_LT(largest, 1e-9); // km, over 764.5 km of flight
}

TEST(CameraPath, SceneKeysInEachForm)
{
    const scene::Scene s = components::loadScene(kData + "/path_forms.toml");
    const std::vector<CameraKey>& keys = s.camera.path.keys();
    ASSERT_EQ(keys.size(), 3u);
    // Heading 90 (east), pitch 20 deg at 67.85 N 20.22 E, 10 km up.
    const scene::LocalFrame local = scene::localFrame(67.85, 20.22);
    EXPECT_LT(glm::length(keys[0].positionKm - scene::planetPoint(67.85, 20.22, 6381.0)), 1e-9);
    const CameraFrame first = scene::frameOf(keys[0].orientation);
    EXPECT_NEAR(std::asin(glm::dot(first.forward, local.up)) * 180.0 / aurorawall::physics::kPi, 20.0, 1e-9);
    EXPECT_NEAR(glm::dot(first.forward, local.north), 0.0, 1e-12);
    EXPECT_GT(glm::dot(first.forward, local.east), 0.0);
    EXPECT_EQ(s.camera.positionKm, keys[0].positionKm);
    EXPECT_LT(glm::length(s.camera.forward - first.forward), 1e-15);
    // Looking at a geographic point, rolled 10 deg: up turns 10 deg from the vertical plane.
    const glm::dvec3 target = scene::planetPoint(69.0, 21.0, 6371.0 + 110.0);
    const CameraFrame second = scene::frameOf(keys[1].orientation);
    EXPECT_NEAR(glm::dot(second.forward, glm::normalize(target - keys[1].positionKm)), 1.0, 1e-12);
    const glm::dvec3 zenith = glm::normalize(keys[1].positionKm);
    const glm::dvec3 level = glm::normalize(zenith - second.forward * glm::dot(zenith, second.forward));
    EXPECT_NEAR(std::acos(glm::dot(second.up, level)) * 180.0 / aurorawall::physics::kPi, 10.0, 1e-9);
    // Looking at a point in the planet frame.
    const CameraFrame third = scene::frameOf(keys[2].orientation);
    EXPECT_NEAR(glm::dot(third.forward, glm::normalize(glm::dvec3(100.0, 0.0, 100.0))), 1.0, 1e-12);
}

// A key's frame as read comes back bit for bit at the key's time and beyond the ends (a recorded flight
// replays its frames exactly); between keys the frame is the quaternions' SQUAD.
TEST(CameraPath, FrameAtAKeysTimeIsTheKeysFrameAsRead)
{
    std::vector<CameraKey> keys;
    for (int i = 0; i < 3; ++i) {
        CameraKey k;
        k.timeS = 0.1 * i;
        const CameraFrame f = turned(0.3 * i);
        k.orientation = scene::orientationOf(f);
        k.frame = f;
        keys.push_back(k);
    }
    const CameraPath path(keys);
    for (const CameraKey& k : keys) {
        const CameraFrame at = path.frameAt(k.timeS);
        EXPECT_EQ(at.forward, k.frame->forward);
        EXPECT_EQ(at.up, k.frame->up);
        EXPECT_NE(scene::frameOf(k.orientation).forward, k.frame->forward); // the quaternion's round trip is not exact
    }
    EXPECT_EQ(path.frameAt(-1.0).forward, keys.front().frame->forward);
    EXPECT_EQ(path.frameAt(9.0).up, keys.back().frame->up);
    const CameraFrame between = path.frameAt(0.05);
    const CameraFrame squad = scene::frameOf(path.orientationAt(0.05));
    EXPECT_EQ(between.forward, squad.forward);
    EXPECT_EQ(between.up, squad.up);
}

TEST(CameraPathErrors, OneLineNamingFileLineAndKey)
{
    EXPECT_EQ(loadError(kData + "/path_one_key.toml"),
              kData + "/path_one_key.toml:5: camera.key: a camera path needs at least 2 keys, got 1");
    EXPECT_EQ(loadError(kData + "/path_time_order.toml"),
              kData + "/path_time_order.toml:14: camera.key.time_s: keys must be in increasing time "
                      "(the previous key is at 10 s)");
    const std::string both = loadError(kData + "/path_two_orientations.toml");
    EXPECT_EQ(both.rfind(kData + "/path_two_orientations.toml:12: camera.key.look_at_km: give one orientation", 0), 0u)
        << both;
    EXPECT_EQ(both.find('\n'), std::string::npos);
}

// Fields of view on the keys: a zoom about the eye, C1 in ln z.

namespace {

// A wall whose own vertical field of view is 70 deg (config/walls/desktop-2x2.toml).
const double kWallTanHalf = std::tan(35.0 * aurorawall::physics::kPi / 180.0);

// Keys with fields of view 60, none (the wall's), 20, 90 and 10 deg at uneven times.
std::vector<CameraKey> zoomKeys()
{
    std::vector<CameraKey> keys = curvedKeys();
    const double fields[] = {60.0, 0.0, 20.0, 90.0, 10.0};
    for (std::size_t i = 0; i < keys.size(); ++i)
        keys[i].fieldOfViewDeg = fields[i];
    return keys;
}

// d(ln z)/dt at t from one side: the second-order one-sided difference of step `step`.
double lnZoomRate(const CameraPath& path, double t, double step)
{
    const auto lnZoom = [&](double u) { return std::log(path.zoomAt(u, kWallTanHalf)); };
    return (-3.0 * lnZoom(t) + 4.0 * lnZoom(t + step) - lnZoom(t + 2.0 * step)) / (2.0 * step);
}

} // namespace

TEST(CameraPathZoom, TheWallsOwnFieldOfViewIsZoomOne)
{
    EXPECT_NEAR(scene::zoomOf(70.0, kWallTanHalf), 1.0, 1e-15);
    // Half the tangent of the half angle: zoom 2, the centre half of the wall's view.
    EXPECT_NEAR(scene::zoomOf(2.0 * std::atan(0.5 * kWallTanHalf) * 180.0 / aurorawall::physics::kPi, kWallTanHalf), 2.0, 1e-15);
    EXPECT_NEAR(scene::zoomOf(90.0, kWallTanHalf), kWallTanHalf, 1e-15);
    EXPECT_EQ(scene::zoomOf(CameraKey{}, kWallTanHalf), 1.0); // a key with neither: the wall's
}

TEST(CameraPathZoom, PassesThroughEachKeysFieldOfView)
{
    std::vector<CameraKey> keys = zoomKeys();
    keys[4].fieldOfViewDeg = 0.0;
    keys[4].zoom = 3.0; // a zoom as `render --record-path` writes it
    const CameraPath path(keys);
    for (const CameraKey& k : keys)
        EXPECT_EQ(path.zoomAt(k.timeS, kWallTanHalf), scene::zoomOf(k, kWallTanHalf)) << k.timeS;
    EXPECT_EQ(path.zoomAt(keys[4].timeS, kWallTanHalf), 3.0);
    EXPECT_EQ(path.zoomAt(keys[1].timeS, kWallTanHalf), 1.0); // no field of view: the wall's
    // Held outside the keys.
    EXPECT_EQ(path.zoomAt(-5.0, kWallTanHalf), scene::zoomOf(60.0, kWallTanHalf));
    EXPECT_EQ(path.zoomAt(100.0, kWallTanHalf), 3.0);
    // A path without fields of view never zooms.
    const CameraPath plain(curvedKeys());
    for (double t = -1.0; t < 14.0; t += 0.37)
        EXPECT_EQ(plain.zoomAt(t, kWallTanHalf), 1.0) << t;
}

TEST(CameraPathZoom, LnZoomIsContinuouslyDifferentiableAtTheKeys)
{
    const std::vector<CameraKey> keys = zoomKeys();
    const CameraPath path(keys);
    const double step = 1e-4;
    for (std::size_t i = 1; i + 1 < keys.size(); ++i) {
        const double t = keys[i].timeS;
        const double before = lnZoomRate(path, t, -step), after = lnZoomRate(path, t, step);
        // The rate is the centred difference of ln z over the neighbouring keys.
        const double centred = (std::log(path.zoomAt(keys[i + 1].timeS, kWallTanHalf)) -
                                std::log(path.zoomAt(keys[i - 1].timeS, kWallTanHalf))) /
                               (keys[i + 1].timeS - keys[i - 1].timeS);
        // Measured: both sides agree with it to 4.7e-8 per s (the differences' truncation at this
        // step); the segments' own mean rates (piecewise-geometric zoom) jump by 0.97 to 2.7 per s.
        EXPECT_NEAR(before, centred, 1e-7) << "key " << i;
        EXPECT_NEAR(after, centred, 1e-7) << "key " << i;
        const auto lnZoomAt = [&](std::size_t k) { return std::log(path.zoomAt(keys[k].timeS, kWallTanHalf)); };
        const double chordBefore = (lnZoomAt(i) - lnZoomAt(i - 1)) / (keys[i].timeS - keys[i - 1].timeS);
        const double chordAfter = (lnZoomAt(i + 1) - lnZoomAt(i)) / (keys[i + 1].timeS - keys[i].timeS);
        EXPECT_GT(std::abs(chordAfter - chordBefore), 0.1) << "key " << i;
    }
    for (double t = -1.0; t < 14.0; t += 0.01)
        EXPECT_GT(path.zoomAt(t, kWallTanHalf), 0.0) << t;
}

TEST(CameraPathZoom, EvenlySpacedLnZoomIsGeometric)
{
    // Fields of view whose ln z steps by ln 2 per key at 2 s per key: z = 2^(t / 2) throughout.
    std::vector<CameraKey> keys;
    for (int i = 0; i < 4; ++i) {
        CameraKey k;
        k.timeS = 2.0 * i;
        k.positionKm = {0.0, 0.0, 6400.0 + i};
        k.fieldOfViewDeg = 2.0 * std::atan(kWallTanHalf / std::pow(2.0, i)) * 180.0 / aurorawall::physics::kPi;
        keys.push_back(k);
    }
    keys[0].fieldOfViewDeg = 70.0;
    const CameraPath path(keys);
    for (double t = 0.0; t <= 6.0; t += 0.125)
        EXPECT_NEAR(path.zoomAt(t, kWallTanHalf), std::pow(2.0, t / 2.0), 1e-14 * std::pow(2.0, t / 2.0)) << t;
}

TEST(CameraPathZoom, TheMastersFrameCarriesThePathsZoom)
{
    const scene::Scene s = components::loadScene(kData + "/path_fov.toml");
    const std::vector<CameraKey>& keys = s.camera.path.keys();
    ASSERT_EQ(keys.size(), 3u);
    EXPECT_EQ(keys[0].fieldOfViewDeg, 0.0);
    EXPECT_EQ(keys[1].fieldOfViewDeg, 20.0);
    EXPECT_EQ(keys[2].fieldOfViewDeg, 90.0);
    EXPECT_EQ(keys[0].zoom, 1.5);
    cluster::ClockSettings settings;
    settings.frames = 0;
    settings.timeStepS = 1.0;
    settings.wallTanHalfFov = kWallTanHalf;
    cluster::MasterClock clock(settings, s.camera, 1.0);
    for (int frame = 0; frame <= 10; ++frame) {
        const cluster::FrameState state = clock.next(false);
        EXPECT_EQ(state.zoom, s.camera.path.zoomAt(frame, kWallTanHalf)) << frame;
    }
    EXPECT_EQ(clock.next(false).zoom, scene::zoomOf(90.0, kWallTanHalf));
    EXPECT_EQ(s.camera.path.zoomAt(0.0, kWallTanHalf), 1.5);
    // A camera without a path keeps the wall's view.
    scene::Camera still = s.camera;
    still.path = {};
    EXPECT_EQ(cluster::MasterClock(settings, still, 1.0).next(false).zoom, 1.0);
}

TEST(CameraPathZoomErrors, TheFieldOfViewLiesStrictlyBetween0And180)
{
    const std::string tail = ": camera.key.field_of_view_deg: must be in (0, 180) degrees, exclusive (got ";
    EXPECT_EQ(loadError(kData + "/path_fov_zero.toml"), kData + "/path_fov_zero.toml:12" + tail + "0)");
    EXPECT_EQ(loadError(kData + "/path_fov_180.toml"), kData + "/path_fov_180.toml:12" + tail + "180)");
    EXPECT_EQ(loadError(kData + "/path_fov_negative.toml"), kData + "/path_fov_negative.toml:12" + tail + "-5)");
    EXPECT_EQ(loadError(kData + "/path_fov_and_zoom.toml"),
              kData + "/path_fov_and_zoom.toml:13: camera.key.zoom: give field_of_view_deg or zoom, not both");
    EXPECT_EQ(loadError(kData + "/path_zoom_zero.toml"),
              kData + "/path_zoom_zero.toml:12: camera.key.zoom: must be a finite number in (0, 1e+06] (got 0)");
}
