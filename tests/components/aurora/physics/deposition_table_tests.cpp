#include "components/aurora/physics/deposition_table.h"
#include "components/aurora/physics/emission.h"
#include "common/glsl.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace aurorawall::components::aurora::physics::f64 {
AURORAWALL_GLSL_PRECISION(double)
#include "components/aurora/deposition_coords.glsl"
} // namespace aurorawall::components::aurora::physics::f64

namespace aurorawall::components::aurora::physics {
namespace {

// Largest relative error of the table lookup against the exact rate over energies between the table's
// energies and altitudes between its texels, where the exact rate is within 20 dB of that energy's peak.
double maxLookupError(const DepositionTableSpec& spec)
{
    DepositionTable table = buildDepositionTable(spec);
    double worst = 0.0;
    for (double fj = 0.37; fj < spec.energyCount - 1; fj += 1.0) {
        double energy = std::exp(table.minLogEnergy + fj * table.logEnergyStep);
        double peak = 0.0;
        for (double z = spec.minAltitudeKm; z <= spec.maxAltitudeKm; z += 0.25)
            peak = std::max(peak, depositionRate(z, energy, spec.spectrum));
        for (double z = spec.minAltitudeKm + 0.31 * spec.altitudeStepKm; z < spec.maxAltitudeKm; z += 0.83 * spec.altitudeStepKm) {
            double exact = depositionRate(z, energy, spec.spectrum);
            if (exact < 1e-2 * peak) continue;
            double lookup = sampleDepositionTable(table, static_cast<float>(z), static_cast<float>(energy));
            worst = std::max(worst, std::abs(lookup / exact - 1.0));
        }
    }
    return worst;
}

TEST(DepositionTable, DefaultSpecHasTheDocumentedShape)
{
    DepositionTable table = buildDepositionTable({});
    EXPECT_EQ(table.altitudeCount, 1081);
    EXPECT_EQ(table.energyCount, 128);
    EXPECT_EQ(table.decibels.size(), 1081u * 128u);
    EXPECT_FLOAT_EQ(table.axes().x, 60.0f);
    EXPECT_FLOAT_EQ(table.axes().y, 0.5f);
}

TEST(DepositionTable, TexelsHoldTheExactRateInDecibels)
{
    DepositionTableSpec spec;
    spec.energyCount = 8;
    spec.altitudeStepKm = 5.0;
    DepositionTable table = buildDepositionTable(spec);
    int i = 10, j = 5; // 110 km
    double energy = std::exp(table.minLogEnergy + j * table.logEnergyStep);
    double exact = 10.0 * std::log10(depositionRate(110.0, energy, spec.spectrum));
    EXPECT_NEAR(table.decibels[j * table.altitudeCount + i], exact, 1e-5);
    EXPECT_GE(*std::min_element(table.decibels.begin(), table.decibels.end()), -200.0f);
}

TEST(DepositionTable, TexCoordsHitTexelCentres)
{
    glm::dvec4 axes(60.0, 0.5, std::log(0.5), 0.1);
    glm::dvec2 size(1081.0, 64.0);
    glm::dvec2 uv = f64::depositionTexCoord(60.0, 0.5, axes, size);
    EXPECT_DOUBLE_EQ(uv.x, 0.5 / 1081.0);
    EXPECT_DOUBLE_EQ(uv.y, 0.5 / 64.0);
    uv = f64::depositionTexCoord(600.0, 0.5 * std::exp(6.3), axes, size);
    EXPECT_NEAR(uv.x, 1080.5 / 1081.0, 1e-15);
    EXPECT_NEAR(uv.y, 63.5 / 64.0, 1e-14);
    EXPECT_NEAR(f64::decibelsToValue(30.0), 1000.0, 1e-10);
}

TEST(DepositionTable, LookupAtTexelsReproducesTheExactRate)
{
    DepositionTable table = buildDepositionTable({});
    double energy = std::exp(table.minLogEnergy + 40 * table.logEnergyStep);
    double lookup = sampleDepositionTable(table, 112.0f, static_cast<float>(energy));
    EXPECT_NEAR(lookup / depositionRate(112.0, energy, Spectrum::Monoenergetic), 1.0, 2e-5);
}

// The worst errors sit on the steep bottom side of monoenergetic profiles (docs/aurora-physics.md).
TEST(DepositionTable, LookupErrorFallsWithResolution)
{
    DepositionTableSpec spec;
    spec.energyCount = 64;
    spec.altitudeStepKm = 2.0; // coarser than the default: keeps the test fast
    double coarse = maxLookupError(spec);
    spec.altitudeStepKm = 1.0;
    double fine = maxLookupError(spec);
    EXPECT_LT(fine, 0.6 * coarse);
    EXPECT_LT(fine, 0.15); // 1 km × 64 energies: 13% measured
    spec.spectrum = Spectrum::Maxwellian;
    spec.energyCount = 16;
    spec.minEnergyKeV = 1.0;
    spec.maxEnergyKeV = 10.0;
    EXPECT_LT(maxLookupError(spec), 0.05); // smooth profiles: 3.1% measured at this coarse energy axis
}

// The largest difference, in dB, between the table's Maxwellian texels and the per-texel quadrature of
// depositionPerEnergyFlux (Simpson, 256 intervals in ln E over [0.01, 30]·E0), over the texels within
// 40 dB, within 80 dB and at any depth below their energy's peak.
struct TexelDifference {
    double within40 = 0.0, within80 = 0.0, anywhere = 0.0;
};

TexelDifference maxwellianTexelDifference(const DepositionTableSpec& spec)
{
    const DepositionTable table = buildDepositionTable(spec);
    TexelDifference worst;
    for (int j = 0; j < table.energyCount; ++j) {
        const double energy = std::exp(table.minLogEnergy + j * table.logEnergyStep);
        std::vector<double> reference(static_cast<size_t>(table.altitudeCount));
        for (int i = 0; i < table.altitudeCount; ++i) {
            const double rate = depositionRate(table.minAltitudeKm + i * table.altitudeStepKm, energy, Spectrum::Maxwellian);
            reference[static_cast<size_t>(i)] = std::max(10.0 * std::log10(rate), spec.floorDecibels);
        }
        const double peak = *std::max_element(reference.begin(), reference.end());
        for (int i = 0; i < table.altitudeCount; ++i) {
            const double below = peak - reference[static_cast<size_t>(i)];
            const double difference =
                std::abs(table.decibels[static_cast<size_t>(j) * table.altitudeCount + i] - reference[static_cast<size_t>(i)]);
            if (below <= 40.0) worst.within40 = std::max(worst.within40, difference);
            if (below <= 80.0) worst.within80 = std::max(worst.within80, difference);
            worst.anywhere = std::max(worst.anywhere, difference);
        }
    }
    return worst;
}

// The table's Maxwellian rows are a convolution of shared monoenergetic values (deposition_table.cpp);
// they must hold what the per-texel quadrature gives. Energy axes with 1, 2 (the default axis) and 5
// quadrature steps per texel step. Measured: 9.5e-7 dB within 40 dB of the peak (the float rounding
// of the stored values, half an ulp at 16-32 dB), 2.0e-5 dB within 80 dB, 0.14 dB anywhere: at
// -200 dB, 225 dB below the peak, where both fixed rules are 0.2 dB off an adaptive quadrature. The
// table's own lookup error is 2e-2 (0.09 dB) and more (docs/aurora-physics.md).
TEST(DepositionTable, MaxwellianTexelsMatchThePerTexelQuadrature)
{
    DepositionTableSpec spec;
    spec.spectrum = Spectrum::Maxwellian;
    spec.altitudeStepKm = 5.0; // the per-texel reference costs 257 evaluations a texel
    for (int energies : {256, 128, 16}) {
        spec.energyCount = energies;
        SCOPED_TRACE(energies);
        const TexelDifference difference = maxwellianTexelDifference(spec);
        EXPECT_LT(difference.within40, 2e-6);
        EXPECT_LT(difference.within80, 1e-4);
        EXPECT_LT(difference.anywhere, 0.5);
    }
}

TEST(DepositionTable, LineYieldTableSharesTheAltitudeAxis)
{
    std::vector<glm::vec4> yields = buildLineYieldTable({});
    ASSERT_EQ(yields.size(), 1081u);
    EXPECT_FLOAT_EQ(yields[100][1], static_cast<float>(lineYield(EmissionLine::Green5577, 110.0)));
}

} // namespace
} // namespace aurorawall::components::aurora::physics
