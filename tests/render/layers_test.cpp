// The ray steps of shaders/render/layers.glsl, composed as the planet, atmosphere and aurora
// components compose them, for hand-built rays: every case of the
// paper's figure 8 (viewer outside the atmosphere), plus viewers inside the aurora layer, inside
// the lower atmosphere and below the ground.
#include "physics/constants.h"
#include "common/glsl.h"

#include <gtest/gtest.h>

#include <cmath>

// An unnamed namespace per test file: each file compiles its own copy of the shared modules.
namespace {
namespace f64 {
AURORAWALL_GLSL_PRECISION(double)
#include "render/ray_sphere.glsl"
#include "render/ray.glsl"
#include "render/layers.glsl"

// What the planet, atmosphere and aurora components find along a ray, in their order.
struct RayLayers {
    bool insideGround;
    real groundT;
    vec2 atmosphere;
    vec2 auroraNear;
    vec2 auroraFar;
};

RayLayers rayLayers(vec3 o, vec3 d, real R, real altitude, real atmosphereTop, real auroraBottom, real auroraTop)
{
    Ray ray = boundByGround(beginRay(o, d, real(0.0)), R, altitude);
    RayLayers l;
    l.insideGround = ray.blocked;
    l.groundT = ray.groundT;
    l.atmosphere = lowerShellSegment(ray, R, atmosphereTop);
    ShellSegments shell = rayShell(o, d, R + auroraBottom, altitude - auroraBottom, R + auroraTop,
                                   altitude - auroraTop, ray.end);
    l.auroraNear = shell.first;
    l.auroraFar = shell.second;
    return l;
}
} // namespace f64
} // namespace



namespace {

constexpr double R = 6371.0, kAtmosphereTop = 75.0, kAuroraBottom = 85.0, kAuroraTop = 300.0;

bool empty(glm::dvec2 s) { return !(s.x < s.y); }

// A ray from `distance` km from the centre whose closest approach is `tangentHeight` km above
// the ground (negative: it would pass below the surface), travelling toward that point.
f64::RayLayers rayPassing(double distance, double tangentHeight)
{
    const double b = R + tangentHeight;
    const glm::dvec3 o(-std::sqrt(distance * distance - b * b), b, 0.0);
    return f64::rayLayers(o, {1, 0, 0}, R, distance - R, kAtmosphereTop, kAuroraBottom, kAuroraTop);
}

// A ray from `altitude` km above the ground at elevation `elevationDeg`.
f64::RayLayers rayFrom(double altitude, double elevationDeg)
{
    const double e = elevationDeg * aurorawall::physics::kPi / 180.0;
    return f64::rayLayers({0, 0, R + altitude}, {std::cos(e), 0, std::sin(e)}, R, altitude, kAtmosphereTop,
                          kAuroraBottom, kAuroraTop);
}

} // namespace

TEST(Layers, Figure8aMissesEverything)
{
    const f64::RayLayers l = rayPassing(R + 1000.0, 400.0);
    EXPECT_FALSE(l.insideGround);
    EXPECT_LT(l.groundT, 0.0);
    EXPECT_TRUE(empty(l.atmosphere));
    EXPECT_TRUE(empty(l.auroraNear));
    EXPECT_TRUE(empty(l.auroraFar));
}

TEST(Layers, Figure8bCrossesOnlyTheAurora)
{
    const f64::RayLayers l = rayPassing(R + 1000.0, 150.0);
    EXPECT_LT(l.groundT, 0.0);
    EXPECT_TRUE(empty(l.atmosphere));
    EXPECT_FALSE(empty(l.auroraNear));
    EXPECT_TRUE(empty(l.auroraFar));
    // The chord of the 300 km sphere at 150 km tangent height: 2 sqrt((R+300)^2 - (R+150)^2).
    const double chord = 2.0 * std::sqrt(std::pow(R + 300.0, 2) - std::pow(R + 150.0, 2));
    EXPECT_NEAR(l.auroraNear.y - l.auroraNear.x, chord, 1e-6);
}

TEST(Layers, Figure8cAuroraThenAtmosphereThenAuroraAgain)
{
    const f64::RayLayers l = rayPassing(R + 1000.0, 50.0);
    EXPECT_LT(l.groundT, 0.0);
    ASSERT_FALSE(empty(l.auroraNear));
    ASSERT_FALSE(empty(l.atmosphere));
    ASSERT_FALSE(empty(l.auroraFar));
    EXPECT_LT(l.auroraNear.y, l.atmosphere.x);
    EXPECT_LT(l.atmosphere.y, l.auroraFar.x);
    EXPECT_FALSE(f64::behindAtmosphere(l.auroraNear, l.atmosphere)); // reaches the eye unattenuated
    EXPECT_TRUE(f64::behindAtmosphere(l.auroraFar, l.atmosphere));   // seen through the air
}

TEST(Layers, Figure8dGroundSeenThroughTheAtmosphereUnderTheAurora)
{
    const f64::RayLayers l = rayPassing(R + 1000.0, -100.0);
    ASSERT_GE(l.groundT, 0.0);
    ASSERT_FALSE(empty(l.auroraNear));
    EXPECT_TRUE(empty(l.auroraFar)); // the far side is hidden by the planet
    EXPECT_LT(l.auroraNear.y, l.atmosphere.x);
    EXPECT_DOUBLE_EQ(l.atmosphere.y, l.groundT);
}

TEST(Layers, ViewerInsideTheAuroraLayer)
{
    // 150 km up, looking level: aurora from the eye on, never below the aurora's bottom.
    const f64::RayLayers level = rayFrom(150.0, 0.0);
    EXPECT_DOUBLE_EQ(level.auroraNear.x, 0.0);
    EXPECT_TRUE(empty(level.atmosphere));
    // Looking 30 deg down: aurora, then the atmosphere, then the ground.
    const f64::RayLayers down = rayFrom(150.0, -30.0);
    EXPECT_DOUBLE_EQ(down.auroraNear.x, 0.0);
    // It leaves the aurora where |o + t d| = R + 85: t = -b - sqrt(b^2 - c), b = o.d, c = |o|^2 - (R+85)^2.
    const double b = -(R + 150.0) * 0.5, c = std::pow(R + 150.0, 2) - std::pow(R + 85.0, 2);
    EXPECT_NEAR(down.auroraNear.y, -b - std::sqrt(b * b - c), 1e-6);
    EXPECT_LT(down.auroraNear.y, down.atmosphere.x);
    EXPECT_GE(down.groundT, down.atmosphere.y - 1e-9);
    EXPECT_TRUE(empty(down.auroraFar));
}

TEST(Layers, ViewerInsideTheLowerAtmosphere)
{
    // On the ground looking up: atmosphere from the eye, then the aurora behind it.
    const f64::RayLayers up = rayFrom(0.0, 60.0);
    EXPECT_LT(up.groundT, 0.0);
    EXPECT_DOUBLE_EQ(up.atmosphere.x, 0.0);
    ASSERT_FALSE(empty(up.auroraNear));
    EXPECT_TRUE(f64::behindAtmosphere(up.auroraNear, up.atmosphere));
    // 10 km up looking down: atmosphere then ground, no aurora.
    const f64::RayLayers down = rayFrom(10.0, -10.0);
    EXPECT_GE(down.groundT, 0.0);
    EXPECT_DOUBLE_EQ(down.atmosphere.x, 0.0);
    EXPECT_DOUBLE_EQ(down.atmosphere.y, down.groundT);
    EXPECT_TRUE(empty(down.auroraNear));
    // 1 m above the ground looking exactly level: the atmosphere, then the aurora far away.
    const f64::RayLayers horizon = rayFrom(0.001, 0.0);
    EXPECT_LT(horizon.groundT, 0.0);
    ASSERT_FALSE(empty(horizon.auroraNear));
    EXPECT_TRUE(f64::behindAtmosphere(horizon.auroraNear, horizon.atmosphere));
}

TEST(Layers, ViewerBelowTheGroundSeesNothing)
{
    EXPECT_TRUE(rayFrom(-1.0, 45.0).insideGround);
    EXPECT_FALSE(rayFrom(0.0, 45.0).insideGround);
}
