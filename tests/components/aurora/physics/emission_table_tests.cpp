#include "components/aurora/physics/emission_table.h"
#include "physics/colour.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

namespace aurorawall::components::aurora::physics {
namespace {

// The exact emission in double, without tables: Σ_lines 0.1 · rate(z, E) · yield(z) · rgb.
glm::dvec3 exactEmission(double altitudeKm, double energyKeV, Spectrum spectrum)
{
    glm::dvec3 rgb(0.0);
    const double rate = depositionRate(altitudeKm, energyKeV, spectrum);
    for (int line = 0; line < kLineCount; ++line)
        rgb += 0.1 * rate * lineYield(static_cast<EmissionLine>(line), altitudeKm) *
               lineLinearSrgbPerRayleigh(static_cast<EmissionLine>(line));
    return rgb;
}

double luminance(glm::dvec3 c)
{
    return 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b;
}

std::vector<float> rowOf(const EmissionTables& tables, double energyKeV)
{
    std::vector<float> row(4 * static_cast<size_t>(tables.nodeCount()));
    emissionRow(tables, energyKeV, row.data());
    return row;
}

// What the shader computed before the rows: the deposition table's lookup (decibels filtered in altitude and
// ln E) times the line yields filtered in altitude, summed over the lines.
glm::dvec3 tableLookupEmission(const EmissionTables& t, double altitudeKm, double energyKeV)
{
    const double deposition = sampleDepositionTable(t.deposition, static_cast<float>(altitudeKm), static_cast<float>(energyKeV));
    const double x = std::clamp((altitudeKm - t.deposition.minAltitudeKm) / t.deposition.altitudeStepKm, 0.0,
                                t.deposition.altitudeCount - 1.0);
    const int i = std::min(static_cast<int>(x), t.deposition.altitudeCount - 2);
    const glm::dvec4 yield = glm::mix(glm::dvec4(t.lineYields[i]), glm::dvec4(t.lineYields[i + 1]), x - i);
    glm::dvec3 rgb(0.0);
    for (int line = 0; line < kLineCount; ++line)
        rgb += 0.1 * deposition * yield[line] * t.lineRgb[line];
    return rgb;
}

struct RowError {
    double worstPoint = 0.0;  // largest relative error where the exact luminance is at least 1e-3 of its peak
    double column = 0.0;      // relative error of the luminance integrated over 85-300 km
};

// The texture's reading of a row between its nodes against the exact emission, 85-300 km (the aurora's shell).
// lookup: the table lookup's instead (tableLookupEmission).
RowError rowError(const EmissionTables& tables, double energyKeV, Spectrum spectrum, bool lookup = false)
{
    const std::vector<float> row = rowOf(tables, energyKeV);
    double peak = 0.0;
    for (double z = 85.0; z <= 300.0; z += 0.05)
        peak = std::max(peak, luminance(exactEmission(z, energyKeV, spectrum)));
    RowError e;
    double exactColumn = 0.0, rowColumn = 0.0;
    for (double z = 85.013; z <= 300.0; z += 0.037) {
        const double exact = luminance(exactEmission(z, energyKeV, spectrum));
        const double sampled = lookup ? luminance(tableLookupEmission(tables, z, energyKeV))
                                      : luminance(glm::dvec3(sampleEmissionRow(tables, row, static_cast<float>(z))));
        exactColumn += exact;
        rowColumn += sampled;
        if (exact >= 1e-3 * peak)
            e.worstPoint = std::max(e.worstPoint, std::abs(sampled / exact - 1.0));
    }
    e.column = std::abs(rowColumn / exactColumn - 1.0);
    return e;
}

TEST(EmissionTable, NodesAreTwiceAsFineAsTheDepositionTable)
{
    const EmissionTables t = buildEmissionTables({});
    EXPECT_EQ(t.nodeCount(), 2 * (t.deposition.altitudeCount - 1) + 1);
    EXPECT_DOUBLE_EQ(t.nodeSpacingKm(), 0.5 * t.deposition.altitudeStepKm);
    EXPECT_FLOAT_EQ(t.axes().x, static_cast<float>(t.deposition.minAltitudeKm));
    EXPECT_FLOAT_EQ(t.axes().z, static_cast<float>(t.nodeCount()));
}

// At the deposition table's own altitudes a node holds what the tables give there: the energy's
// decibels between the table's rows, the yields of that altitude, summed over the lines.
TEST(EmissionTable, NodesAtTheTablesAltitudesHoldTheTablesEmission)
{
    const EmissionTables t = buildEmissionTables({});
    for (double energy : {0.6, 3.7, 12.0, 41.0}) {
        const std::vector<float> row = rowOf(t, energy);
        for (int i : {10, 60, 200, 500}) {
            const double z = t.deposition.minAltitudeKm + i * t.deposition.altitudeStepKm;
            const double deposition = sampleDepositionTable(t.deposition, static_cast<float>(z), static_cast<float>(energy));
            glm::dvec3 expected(0.0);
            for (int line = 0; line < kLineCount; ++line)
                expected += 0.1 * deposition * double(t.lineYields[i][line]) * t.lineRgb[line];
            const size_t k = static_cast<size_t>(i) * kEmissionSubdivisions;
            for (int channel = 0; channel < 3; ++channel)
                EXPECT_NEAR(row[4 * k + channel], expected[channel], 1e-4 * std::abs(expected[channel]) + 1e-30)
                    << "E " << energy << " keV, z " << z << " km, channel " << channel;
        }
    }
}

// Linear interpolation between nodes, where the table lookup interpolates the deposition in decibels:
// against the exact emission, wherever it exceeds 1e-3 of its peak, the rows err by at most 0.5% more
// than the lookup did and their column by at most 1e-4 more, for both spectra across the table's
// energies (the energy's interpolation between the table's rows dominates both).
TEST(EmissionTable, RowsReadBetweenNodesStayNearTheExactEmission)
{
    for (Spectrum spectrum : {Spectrum::Monoenergetic, Spectrum::Maxwellian}) {
        DepositionTableSpec spec;
        spec.spectrum = spectrum;
        const EmissionTables t = buildEmissionTables(spec);
        for (double energy : {0.7, 2.5, 9.0, 20.0, 45.0}) {
            const RowError e = rowError(t, energy, spectrum);
            const RowError before = rowError(t, energy, spectrum, true);
            std::printf("%s %5.1f keV: worst %.2e (lookup %.2e), column %.2e (lookup %.2e)\n",
                        spectrum == Spectrum::Maxwellian ? "maxwellian" : "monoenergetic", energy, e.worstPoint,
                        before.worstPoint, e.column, before.column);
            EXPECT_LT(e.worstPoint, before.worstPoint + 0.005) << energy << " keV";
            EXPECT_LT(e.column, before.column + 1e-4) << energy << " keV";
        }
    }
}

// Energies beyond the table's range take its end rows (as the texture's clamp to edge did).
TEST(EmissionTable, EnergiesBeyondTheTableTakeItsEndRows)
{
    const EmissionTables t = buildEmissionTables({});
    EXPECT_EQ(rowOf(t, 80.0), rowOf(t, 50.0));
    EXPECT_EQ(rowOf(t, 0.2), rowOf(t, 0.5));
}

} // namespace
} // namespace aurorawall::components::aurora::physics
