// Tests of the several-lights sky: closed form against the nested-march reference,
// linearity in the lights, extreme geometries.
#include "physics/atmosphere/sky_accuracy.h"
#include "physics/constants.h"

#include <gtest/gtest.h>

#include <cmath>

namespace aurorawall::physics::atmosphere {
namespace {

const SkyAtmosphereParameters kAir;

double maxRelative(const std::vector<glm::dvec3>& values, const std::vector<glm::dvec3>& reference)
{
    return skyErrors(values, reference).maxRelativeError;
}

// With the same outer march (M = 64), the closed-form light depth agrees with a nested march of
// K = 4096 light steps (double) within 2e-5 for 1 to 8 Sun positions;
// the float closed form (the shader's arithmetic) within 5e-4. Measured: 1.1e-5 (double: the half-line
// airmass errs by about 1e-6 on these paths, and the transmittance e^{−β·I} multiplies a relative error
// of I by β·I, up to about 20 in blue on light paths that graze the ground) and 1.8e-4 (float, mostly
// the outer march's own float positions).
TEST(Sky, ClosedFormMatchesNestedMarchForOneToEightLights)
{
    const std::vector<SkyView> views = twilightViews(0.002);
    for (int lightCount = 1; lightCount <= kSkyMaxLights; ++lightCount) {
        const std::vector<SkyLight> suns = twilightSuns(lightCount);
        const auto reference = skyRadiances(views, kAir, suns, SkyLightMethod::NestedMarch, 64, 4096, AirmassPrecision::Float64);
        const auto closed64 = skyRadiances(views, kAir, suns, SkyLightMethod::ClosedForm, 64, 0, AirmassPrecision::Float64);
        const auto closed32 = skyRadiances(views, kAir, suns, SkyLightMethod::ClosedForm, 64, 0, AirmassPrecision::Float32);
        EXPECT_LT(maxRelative(closed64, reference), 2e-5) << lightCount << " lights";
        EXPECT_LT(maxRelative(closed32, reference), 5e-4) << lightCount << " lights";
    }
}

// The twilight case is not trivial: the sky toward the Sun is brighter than away from it, and some
// views (low, away from the Sun) lie wholly in the Earth's shadow.
TEST(Sky, TwilightSkyHasGlowAndShadow)
{
    const std::vector<SkyView> views = twilightViews(0.002); // view 0: toward the Sun at the horizon
    const auto radiance = skyRadiances(views, kAir, twilightSuns(1), SkyLightMethod::ClosedForm, 32, 0, AirmassPrecision::Float64);
    const glm::dvec3 towardSun = radiance[1], awayLow = radiance[4 * 6], zenith = radiance.back();
    EXPECT_GT(towardSun.r, 10.0 * zenith.r);
    EXPECT_EQ(awayLow, glm::dvec3(0.0));
    EXPECT_GT(zenith.b, 0.5) << "civil-twilight zenith: a few cd/m^2";
    EXPECT_LT(zenith.b, 50.0);
}

// Single scattering is linear in the lights: N lights give the sum of N one-light skies
// (1e-12 in double, 1e-5 in float), for both light-depth methods.
TEST(Sky, SeveralLightsAreTheSumOfSingleLights)
{
    const std::vector<SkyView> views = twilightViews(0.002);
    const std::vector<SkyLight> suns = twilightSuns(kSkyMaxLights);
    for (SkyLightMethod method : {SkyLightMethod::ClosedForm, SkyLightMethod::NestedMarch}) {
        for (AirmassPrecision precision : {AirmassPrecision::Float64, AirmassPrecision::Float32}) {
            std::vector<glm::dvec3> sum(views.size(), glm::dvec3(0.0));
            for (const SkyLight& sun : suns) {
                const auto one = skyRadiances(views, kAir, {sun}, method, 16, 8, precision);
                for (size_t i = 0; i < views.size(); ++i) sum[i] += one[i];
            }
            const auto all = skyRadiances(views, kAir, suns, method, 16, 8, precision);
            EXPECT_LT(maxRelative(all, sum), precision == AirmassPrecision::Float64 ? 1e-12 : 1e-5);
        }
    }
}

// Finite, non-negative radiance for the Sun exactly at the horizon, below it (−0.1° to the nadir), at
// the zenith, and for viewers exactly on the ground, 1 m up, and in space (400 km and geostationary,
// looking at the limb, at the planet and away from it), in float and double, both methods.
TEST(Sky, NoNanOrInfAtExtremes)
{
    std::vector<SkyLight> suns;
    for (double elevation : {0.0, -0.1, -2.0, -8.0, -45.0, -90.0, 30.0, 90.0})
        suns.push_back({twilightDirection(0.0, elevation), glm::dvec3(1.28e5)});
    const glm::dvec3 up = twilightFrame().up;
    std::vector<SkyView> views = twilightViews(0.0);
    for (const SkyView& view : twilightViews(0.001)) views.push_back(view);
    for (double altitude : {400.0, 35786.0}) {
        const glm::dvec3 origin = (kAir.planetRadiusKm + altitude) * up;
        const double limb = std::acos(kAir.planetRadiusKm / (kAir.planetRadiusKm + altitude)) * 180.0 / aurorawall::physics::kPi;
        for (double elevation : {-90.0, -limb, -limb + 0.5, -limb - 0.5, 0.0, 90.0})
            views.push_back({origin, twilightDirection(30.0, elevation), 1e30});
    }
    views.push_back({up * kAir.planetRadiusKm, glm::dvec3(0.0), 1e30}); // zero direction
    for (const SkyLight& sun : suns)
        for (SkyLightMethod method : {SkyLightMethod::ClosedForm, SkyLightMethod::NestedMarch})
            for (AirmassPrecision precision : {AirmassPrecision::Float64, AirmassPrecision::Float32})
                for (const glm::dvec3& value : skyRadiances(views, kAir, {sun}, method, 16, 8, precision))
                    for (int c = 0; c < 3; ++c) {
                        ASSERT_TRUE(std::isfinite(value[c]));
                        ASSERT_GE(value[c], 0.0);
                    }
}

} // namespace
} // namespace aurorawall::physics::atmosphere
