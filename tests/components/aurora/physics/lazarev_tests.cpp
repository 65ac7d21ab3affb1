#include "components/aurora/physics/atmosphere_profile.h"
#include "components/aurora/physics/lazarev.h"
#include "physics/constants.h"
#include "quadrature.h"

#include <gtest/gtest.h>

#include <cmath>

namespace aurorawall::components::aurora::physics {
namespace {

using testing::adaptiveSimpson;
using testing::piecewiseSimpson;
using testing::peakAltitude;

TEST(Lazarev, RateAtZeroDepthIs048)
{
    EXPECT_DOUBLE_EQ(lazarevRate(0.0), 0.48);
}

TEST(Lazarev, RatePeaksAt0993NearHalf)
{
    double rPeak = 0.0;
    for (double r = 0.0; r < 3.0; r += 1e-5)
        if (lazarevRate(r) > lazarevRate(rPeak)) rPeak = r;
    EXPECT_NEAR(lazarevRate(rPeak), 0.993, 0.001);
    EXPECT_NEAR(rPeak, 0.5, 0.05);
}

TEST(Lazarev, RateIntegralMatchesItsClosedForm)
{
    // ∫_0^∞ 4.2 r e^{−r²−r} dr = 4.2 (½ − (√π/4) e^{1/4} erfc(½)) (complete the square, r + ½ = t);
    // ∫_0^∞ 0.48 e^{−17.4 r^1.37} dr = 0.48 Γ(1 + 1/1.37) / 17.4^{1/1.37}.
    const double closedForm = 4.2 * (0.5 - std::sqrt(aurorawall::physics::kPi) / 4.0 * std::exp(0.25) * std::erfc(0.5)) +
                              0.48 * std::tgamma(1.0 + 1.0 / 1.37) / std::pow(17.4, 1.0 / 1.37);
    EXPECT_NEAR(lazarevRateIntegral() / closedForm, 1.0, 1e-14);
    EXPECT_NEAR(lazarevRateIntegral(), 1.0, 0.01); // Lazarev's L is normalised to about 1
}

TEST(Lazarev, PeakAltitudesMatchReference)
{
    // Published peak altitudes of the Lazarev profile over USSA76: 1 keV 157 km, 5 keV 112.5 km, 10 keV 104.7 km.
    const double expected[][2] = {{1.0, 157.0}, {5.0, 112.5}, {10.0, 104.7}};
    for (const auto& [energy, altitude] : expected) {
        double peak = peakAltitude([&](double z) { return depositionPerElectron(z, energy); }, 80.0, 300.0);
        EXPECT_NEAR(peak, altitude, 1.0) << energy << " keV";
    }
}

TEST(Lazarev, PeakFallsWithEnergy)
{
    double previous = 1e9;
    for (double energy : {1.0, 2.0, 5.0, 10.0, 20.0, 30.0}) {
        double peak = peakAltitude([&](double z) { return depositionPerElectron(z, energy); }, 70.0, 300.0);
        EXPECT_LT(peak, previous) << energy << " keV";
        previous = peak;
    }
}

// dM = −D dz turns ∫ A dz = ∫ L(M/M_E)·E·D/M_E dz into E·∫ L(r) dr.
TEST(Lazarev, ColumnDepositionIsEnergyTimesRateIntegral)
{
    for (double energy : {1.0, 5.0, 10.0, 30.0}) {
        double column =
            1e5 * piecewiseSimpson([&](double z) { return depositionPerElectron(z, energy); }, 60.0, 6000.0, 2.0, 1e-10);
        double rMax = shieldingMass(60.0) / characteristicMass(energy);
        double rMin = shieldingMass(6000.0) / characteristicMass(energy);
        double expected = energy * adaptiveSimpson(lazarevRate, rMin, std::min(rMax, 12.0), 1e-13);
        EXPECT_NEAR(column / expected, 1.0, 1e-7) << energy << " keV";
    }
}

// Fixed total energy flux: every spectrum deposits ∫ L dr of it (all of it stops above 60 km).
TEST(Lazarev, MaxwellianDepositsTheNormalisedEnergyFlux)
{
    for (double e0 : {0.5, 2.0, 5.0}) {
        double column = 1e5 * piecewiseSimpson(
            [&](double z) { return depositionPerEnergyFlux(z, e0, Spectrum::Maxwellian); }, 60.0, 6000.0, 5.0, 1e-8);
        EXPECT_NEAR(column / lazarevRateIntegral(), 1.0, 2e-4) << "E0 = " << e0 << " keV";
    }
}

TEST(Lazarev, MaxwellianPeaksBetweenItsCharacteristicAndMeanEnergy)
{
    double peak = peakAltitude([](double z) { return depositionPerEnergyFlux(z, 5.0, Spectrum::Maxwellian); }, 80.0, 300.0);
    double atE0 = peakAltitude([](double z) { return depositionPerElectron(z, 5.0); }, 80.0, 300.0);
    double atE20 = peakAltitude([](double z) { return depositionPerElectron(z, 20.0); }, 80.0, 300.0);
    EXPECT_LT(peak, atE0);
    EXPECT_GT(peak, atE20);
}

} // namespace
} // namespace aurorawall::components::aurora::physics
