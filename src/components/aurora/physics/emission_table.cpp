#include "components/aurora/physics/emission_table.h"

#include "physics/colour.h"
#include "common/glsl.h"

#include <algorithm>
#include <cmath>

namespace aurorawall::components::aurora::physics {
namespace {
AURORAWALL_GLSL_PRECISION(float)
#include "components/aurora/deposition_coords.glsl"
} // namespace

int EmissionTables::nodeCount() const
{
    return (deposition.altitudeCount - 1) * kEmissionSubdivisions + 1;
}

double EmissionTables::nodeSpacingKm() const
{
    return deposition.altitudeStepKm / kEmissionSubdivisions;
}

glm::vec3 EmissionTables::axes() const
{
    return {static_cast<float>(deposition.minAltitudeKm), static_cast<float>(nodeSpacingKm()),
            static_cast<float>(nodeCount())};
}

EmissionTables buildEmissionTables(const DepositionTableSpec& spec)
{
    EmissionTables t;
    t.deposition = buildDepositionTable(spec);
    t.lineYields = buildLineYieldTable(spec);
    for (int line = 0; line < kLineCount; ++line)
        t.lineRgb[line] = lineLinearSrgbPerRayleigh(static_cast<EmissionLine>(line));
    return t;
}

void emissionRow(const EmissionTables& tables, double energyKeV, float* out)
{
    const DepositionTable& d = tables.deposition;
    // The energy's place between the table's rows, clamped to its ends; the row's decibels at the table's altitudes.
    const double j = std::clamp((std::log(energyKeV) - d.minLogEnergy) / d.logEnergyStep, 0.0,
                                static_cast<double>(d.energyCount - 1));
    const int j0 = std::min(static_cast<int>(j), d.energyCount - 2); // the table has at least 2 energies
    const double w = j - j0;
    const float* lo = &d.decibels[static_cast<size_t>(j0) * d.altitudeCount];
    const float* hi = lo + d.altitudeCount;
    std::vector<double> decibels(static_cast<size_t>(d.altitudeCount));
    for (int i = 0; i < d.altitudeCount; ++i)
        decibels[i] = lo[i] + w * (hi[i] - lo[i]);
    // The lines' colours weighted by their yields at the table's altitudes.
    std::vector<glm::dvec3> lineSum(static_cast<size_t>(d.altitudeCount), glm::dvec3(0.0));
    for (int i = 0; i < d.altitudeCount; ++i)
        for (int line = 0; line < kLineCount; ++line)
            lineSum[i] += double(tables.lineYields[i][line]) * tables.lineRgb[line];
    const double log2TenOverTen = 0.332192809488736235; // 10^(dB/10) = 2^(dB·log2(10)/10)
    const int nodes = tables.nodeCount();
    for (int k = 0; k < nodes; ++k) {
        const int i = std::min(k / kEmissionSubdivisions, d.altitudeCount - 2);
        const double f = static_cast<double>(k - i * kEmissionSubdivisions) / kEmissionSubdivisions;
        const double db = decibels[i] + f * (decibels[i + 1] - decibels[i]);
        const glm::dvec3 rgb = 0.1 * std::exp2(db * log2TenOverTen) * glm::mix(lineSum[i], lineSum[i + 1], f);
        out[4 * k] = static_cast<float>(rgb.r);
        out[4 * k + 1] = static_cast<float>(rgb.g);
        out[4 * k + 2] = static_cast<float>(rgb.b);
        out[4 * k + 3] = 0.0f;
    }
}

glm::vec3 sampleEmissionRow(const EmissionTables& tables, const std::vector<float>& row, float altitudeKm)
{
    const LinearTaps x = linearTaps(emissionTexCoord(altitudeKm, tables.axes()), tables.nodeCount());
    auto node = [&](int i) { return glm::vec3(row[4 * i], row[4 * i + 1], row[4 * i + 2]); };
    return node(x.i0) + x.weight * (node(x.i1) - node(x.i0));
}

} // namespace aurorawall::components::aurora::physics
