// The shared ray-sphere module (shaders/render/ray_sphere.glsl), compiled as C++ in float (as the
// GPU runs it) and double (the reference).
#include "physics/constants.h"
#include "common/glsl.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

// An unnamed namespace per test file: each file compiles its own copy of the shared modules.
namespace {
namespace f32 {
AURORAWALL_GLSL_PRECISION(float)
#include "render/ray_sphere.glsl"
} // namespace f32
namespace f64 {
AURORAWALL_GLSL_PRECISION(double)
#include "render/ray_sphere.glsl"
} // namespace f64
} // namespace



namespace {
constexpr double R = 6371.0;

// Float result of the shared module for an origin at altitude `altitude` above the sphere
// (altitude supplied in double, as the renderer does).
glm::dvec2 floatHit(glm::dvec3 o, glm::dvec3 d, double r)
{
    const glm::vec2 h = f32::raySphere(glm::vec3(o), glm::vec3(glm::normalize(d)), float(r), float(glm::length(o) - r));
    return glm::dvec2(h);
}

glm::dvec2 exactHit(glm::dvec3 o, glm::dvec3 d, double r)
{
    return f64::raySphere(o, glm::normalize(d), r, glm::length(o) - r);
}
} // namespace

TEST(RaySphere, MissesAndHits)
{
    const glm::dvec2 miss = exactHit({0, 0, 2 * R}, {1, 0, 0}, R);
    EXPECT_GT(miss.x, miss.y);
    const glm::dvec2 hit = exactHit({0, 0, 2 * R}, {0, 0, -1}, R);
    EXPECT_NEAR(hit.x, R, 1e-9);
    EXPECT_NEAR(hit.y, 3 * R, 1e-9);
}

TEST(RaySphere, GroundObserverLookingDownHitsAtItsAltitude)
{
    // 1 m above the ground, looking straight down: the ground is 1 m away. Naive float
    // |o|^2 - r^2 loses this completely at 6371 km (one ulp is 0.49 m).
    const glm::dvec3 o(0, 0, R + 0.001);
    const glm::dvec2 h = floatHit(o, {0, 0, -1}, R);
    EXPECT_NEAR(h.x, 0.001, 1e-6);
}

TEST(RaySphere, GrazingRaysFromSpaceAreAccurateInFloat)
{
    // From 400 km, geostationary orbit and 10^6 km, rays passing 0.1 to 74.9 km above the
    // surface, against the top of a 75 km atmosphere. Near tangency the crossing point slides
    // along the ray (a conditioning limit of any float method), but the point found lies on
    // the sphere: its altitude, evaluated in double along the traced ray, is within a metre of
    // the shell, or within float's resolution of the distance from the camera when that is larger.
    // A naive float form (b^2 - c with c = |o|^2 - r^2) is off by tens to hundreds of metres.
    const double top = R + 75.0;
    for (double distance : {R + 400.0, R + 35786.0, 1.0e6}) {
        for (double tangentHeight : {0.1, 1.0, 10.0, 50.0, 74.0, 74.9}) {
            const double b = R + tangentHeight; // impact parameter
            const glm::dvec3 o(-std::sqrt(distance * distance - b * b), b, 0.0);
            const glm::dvec3 d(1, 0, 0);
            const glm::dvec2 exact = exactHit(o, d, top);
            const glm::dvec2 single = floatHit(o, d, top);
            ASSERT_LT(exact.x, exact.y);
            ASSERT_LT(single.x, single.y);
            // The GPU traces the ray from the float-rounded camera position (62 m ulp at 10^6 km).
            const glm::dvec3 traced = glm::dvec3(glm::vec3(o));
            // Bound: a metre, or two float ulps of the distance travelled (31 m at 10^6 km).
            for (double t : {single.x, single.y})
                EXPECT_NEAR(glm::length(traced + t * d) - top, 0.0, std::max(1e-3, 2.0 * t * 0x1p-24))
                    << distance << " " << tangentHeight;
        }
    }
}

TEST(RaySphere, ShellSplitsAroundTheInnerSphere)
{
    // A ray from inside the aurora layer that dips below its bottom and comes back up gives
    // two segments. Looking up: one segment from the camera to the top.
    const double bottom = R + 85.0, top = R + 300.0;
    const glm::dvec3 o(0, 0, R + 100.0);
    const double down = 10.0 * aurorawall::physics::kPi / 180.0; // 10 deg below the horizontal: lowest point 6372.7 km
    const glm::dvec3 slanting(std::cos(down), 0.0, -std::sin(down));
    const f64::ShellSegments level = f64::rayShell(o, slanting, bottom, 15.0, top, -200.0, 1e30);
    EXPECT_DOUBLE_EQ(level.first.x, 0.0);
    EXPECT_LT(level.first.x, level.first.y);
    EXPECT_LT(level.second.x, level.second.y);
    EXPECT_GT(level.second.x, level.first.y);
    // The float evaluation finds the same two parts within float resolution of the distances.
    const f32::ShellSegments single = f32::rayShell(glm::vec3(o), glm::vec3(slanting), float(bottom), 15.0f, float(top),
                                                    -200.0f, 1e30f);
    EXPECT_NEAR(single.first.y, level.first.y, 4e-7 * level.first.y + 1e-3);
    EXPECT_NEAR(single.second.x, level.second.x, 4e-7 * level.second.x + 1e-3);
    const f64::ShellSegments up = f64::rayShell(o, {0, 0, 1}, bottom, 15.0, top, -200.0, 1e30);
    EXPECT_NEAR(up.first.y, 200.0, 1e-9);
    EXPECT_GT(up.second.x, up.second.y);
}
