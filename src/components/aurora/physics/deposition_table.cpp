#include "components/aurora/physics/deposition_table.h"

#include "components/aurora/physics/atmosphere_profile.h"
#include "components/aurora/physics/emission.h"
#include "common/glsl.h"

#include <algorithm>
#include <cmath>

namespace aurorawall::aurora::f32 {
AURORAWALL_GLSL_PRECISION(float)
#include "components/aurora/deposition_coords.glsl"
} // namespace aurorawall::aurora::f32

namespace aurorawall::aurora {
namespace {

int altitudeCountOf(const DepositionTableSpec& spec)
{
    return static_cast<int>(std::lround((spec.maxAltitudeKm - spec.minAltitudeKm) / spec.altitudeStepKm)) + 1;
}

// GL_LINEAR along one axis with clamp-to-edge: texel coordinate x = u·n − 1/2, neighbours
// floor(x) and floor(x) + 1 clamped to [0, n − 1], weight fract(x).
struct LinearTaps {
    int i0, i1;
    float weight;
};

LinearTaps linearTaps(float u, int n)
{
    float x = u * static_cast<float>(n) - 0.5f;
    float base = std::floor(x);
    int i = static_cast<int>(base);
    return {std::clamp(i, 0, n - 1), std::clamp(i + 1, 0, n - 1), x - base};
}

} // namespace

glm::vec4 DepositionTable::axes() const
{
    return {static_cast<float>(minAltitudeKm), static_cast<float>(altitudeStepKm),
            static_cast<float>(minLogEnergy), static_cast<float>(logEnergyStep)};
}

glm::vec2 DepositionTable::size() const
{
    return {static_cast<float>(altitudeCount), static_cast<float>(energyCount)};
}

double depositionRate(double altitudeKm, double energyKeV, Spectrum spectrum)
{
    return depositionPerEnergyFlux(altitudeKm, energyKeV, spectrum) * kKeVPerErg;
}

DepositionTable buildDepositionTable(const DepositionTableSpec& spec)
{
    DepositionTable table;
    table.altitudeCount = altitudeCountOf(spec);
    table.energyCount = spec.energyCount;
    table.minAltitudeKm = spec.minAltitudeKm;
    table.altitudeStepKm = spec.altitudeStepKm;
    table.minLogEnergy = std::log(spec.minEnergyKeV);
    table.logEnergyStep = (std::log(spec.maxEnergyKeV) - table.minLogEnergy) / (spec.energyCount - 1);
    table.decibels.resize(static_cast<size_t>(table.altitudeCount) * table.energyCount);
    for (int i = 0; i < table.altitudeCount; ++i) {
        const double altitudeKm = spec.minAltitudeKm + i * spec.altitudeStepKm;
        const double density = massDensity(altitudeKm), shielding = shieldingMass(altitudeKm);
        for (int j = 0; j < table.energyCount; ++j) {
            double energyKeV = std::exp(table.minLogEnergy + j * table.logEnergyStep);
            double rate = depositionPerEnergyFlux(density, shielding, energyKeV, spec.spectrum) * kKeVPerErg;
            double decibels = rate > 0.0 ? 10.0 * std::log10(rate) : spec.floorDecibels;
            table.decibels[static_cast<size_t>(j) * table.altitudeCount + i] =
                static_cast<float>(std::max(decibels, spec.floorDecibels));
        }
    }
    return table;
}

float sampleDepositionTable(const DepositionTable& table, float altitudeKm, float energyKeV)
{
    glm::vec2 uv = f32::depositionTexCoord(altitudeKm, energyKeV, table.axes(), table.size());
    LinearTaps x = linearTaps(uv.x, table.altitudeCount);
    LinearTaps y = linearTaps(uv.y, table.energyCount);
    auto texel = [&](int i, int j) { return table.decibels[static_cast<size_t>(j) * table.altitudeCount + i]; };
    float bottom = texel(x.i0, y.i0) + x.weight * (texel(x.i1, y.i0) - texel(x.i0, y.i0));
    float top = texel(x.i0, y.i1) + x.weight * (texel(x.i1, y.i1) - texel(x.i0, y.i1));
    return f32::decibelsToValue(bottom + y.weight * (top - bottom));
}

std::vector<glm::vec4> buildLineYieldTable(const DepositionTableSpec& spec)
{
    std::vector<glm::vec4> yields(static_cast<size_t>(altitudeCountOf(spec)));
    for (size_t i = 0; i < yields.size(); ++i) {
        double altitudeKm = spec.minAltitudeKm + static_cast<double>(i) * spec.altitudeStepKm;
        for (int line = 0; line < kLineCount; ++line) {
            yields[i][line] = static_cast<float>(lineYield(static_cast<EmissionLine>(line), altitudeKm));
        }
    }
    return yields;
}

} // namespace aurorawall::aurora
