#include "components/aurora/physics/atmosphere_profile.h"
#include "quadrature.h"

#include <gtest/gtest.h>

#include <cmath>

namespace aurorawall::components::aurora::physics {
namespace {

using testing::piecewiseSimpson;

TEST(AtmosphereProfile, DensityMatchesTheUssa76TableAtItsAltitudes)
{
    EXPECT_NEAR(massDensity(75.0), 3.9921e-8, 1e-14);      // g/cm³ = 1e-3 kg/m³
    EXPECT_NEAR(massDensity(100.0) / 5.604e-10, 1.0, 1e-12);
    EXPECT_NEAR(massDensity(1000.0) / 3.561e-18, 1.0, 1e-12);
}

TEST(AtmosphereProfile, DensityIsLogLinearBetweenTableAltitudes)
{
    EXPECT_NEAR(massDensity(80.0), std::sqrt(3.9921e-8 * 8.2196e-9), 1e-20);
    EXPECT_NEAR(massDensity(107.5) / std::sqrt(5.604e-10 * 4.289e-11), 1.0, 1e-12);
}

TEST(AtmosphereProfile, ShieldingMassMatchesAdaptiveQuadrature)
{
    for (double z : {60.0, 75.0, 90.0, 104.7, 112.5, 157.0, 333.3, 600.0, 999.0}) {
        double exact = shieldingMass(z);
        // Above 1000 km the density keeps its last scale height (155 km): 6000 km is 32 of them.
        double quadrature = 1e5 * piecewiseSimpson(massDensity, z, 6000.0, 5.0, 1e-12);
        EXPECT_NEAR(quadrature / exact, 1.0, 1e-9) << "z = " << z;
    }
}

TEST(AtmosphereProfile, ShieldingMassDerivativeIsMinusDensity)
{
    for (double z : {65.0, 99.0, 140.0, 420.0}) {
        double h = 1e-3; // km
        double derivative = (shieldingMass(z + h) - shieldingMass(z - h)) / (2e5 * h);
        EXPECT_NEAR(-derivative / massDensity(z), 1.0, 1e-6) << "z = " << z;
    }
}

TEST(AtmosphereProfile, TemperatureFollowsTheUssa76DefiningLayers)
{
    EXPECT_NEAR(temperatureK(60.0), 247.02, 0.02);
    EXPECT_NEAR(temperatureK(100.0), 195.08, 0.01);
    EXPECT_NEAR(temperatureK(115.0), 300.0, 1e-9);
    EXPECT_NEAR(temperatureK(150.0), 634.39, 0.01);
    EXPECT_NEAR(temperatureK(200.0), 854.56, 0.01);
    EXPECT_NEAR(temperatureK(500.0), 999.24, 0.01);
}

TEST(AtmosphereProfile, NumberDensitiesAddUpToTheMassDensity)
{
    for (double z : {70.0, 100.0, 150.0, 300.0}) {
        NumberDensities n = numberDensities(z);
        double mass = (28.9644 * (n.n2 + n.o2) + 15.9994 * n.o) * 1.66053906660e-24;
        EXPECT_NEAR(mass / massDensity(z), 1.0, 1e-12);
    }
    // USSA76 at 100 km: 1.19e13 cm⁻³ in all.
    EXPECT_NEAR(numberDensities(100.0).total() / 1.19e13, 1.0, 0.02);
    EXPECT_GT(atomicOxygenFraction(250.0), 0.5);
    EXPECT_LT(atomicOxygenFraction(90.0), 0.01);
}

} // namespace
} // namespace aurorawall::components::aurora::physics
