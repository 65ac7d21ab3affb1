#include "components/aurora/physics/deposition_table.h"

#include "components/aurora/physics/atmosphere_profile.h"
#include "components/aurora/physics/emission.h"
#include "common/glsl.h"

#include <algorithm>
#include <cmath>

namespace aurorawall::components::aurora::physics::f32 {
AURORAWALL_GLSL_PRECISION(float)
#include "components/aurora/deposition_coords.glsl"
} // namespace aurorawall::components::aurora::physics::f32

namespace aurorawall::components::aurora::physics {
namespace {

int altitudeCountOf(const DepositionTableSpec& spec)
{
    return static_cast<int>(std::lround((spec.maxAltitudeKm - spec.minAltitudeKm) / spec.altitudeStepKm)) + 1;
}

} // namespace

LinearTaps linearTaps(float u, int n)
{
    float x = u * static_cast<float>(n) - 0.5f;
    float base = std::floor(x);
    int i = static_cast<int>(base);
    return {std::clamp(i, 0, n - 1), std::clamp(i + 1, 0, n - 1), x - base};
}

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

namespace {

// 10·log10(rate·kKeVPerErg) stored as float, floored at the spec's floor.
float decibelsOf(double depositionPerEnergyFluxPerCm, double floorDecibels)
{
    const double rate = depositionPerEnergyFluxPerCm * kKeVPerErg;
    const double decibels = rate > 0.0 ? 10.0 * std::log10(rate) : floorDecibels;
    return static_cast<float>(std::max(decibels, floorDecibels));
}

// The Maxwellian of aurora/lazarev.h as a discrete convolution in ln E. With E = E0·x, u = ln x
// and the monoenergetic m(z, ln E) = A(z, E)/E,
//   ∫ φ A dE / (2 E0³) = ½ ∫ x³ e^{−x} m(z, ln E0 + u) du over u in [ln 0.01, ln 30],
// the limits of the per-texel rule. A step h that divides the table's ln E step Δ (h = Δ/k, the
// smallest k giving h ≤ 1/32, as fine as the per-texel rule's 256 intervals) puts every texel's
// nodes u_n = ln 0.01 + n·h on one grid ln E_p = ln E_min + ln 0.01 + p·h, so m is evaluated once
// per (altitude, grid node) and shared by all energies. Simpson's rule covers the first 2M ≤ span/h
// intervals; the rest, [u_2M, ln 30] (shorter than 2h), is the integral of the cubic through
// u_2M−2, u_2M−1, u_2M and ln 30, whose node ln E0 + ln 30 lies on a second grid of one node per
// energy. Both limits are the per-texel rule's, so the two differ only by their quadrature errors.
// The default table (Δ = 0.0363, k = 2): 823 evaluations per altitude instead of 128 × 257.
struct MaxwellianRule {
    double lowestU = 0.0;        // ln 0.01
    double step = 0.0;           // h
    int substeps = 1;            // k = Δ/h
    std::vector<double> weights; // ½ x³ e^{−x} × quadrature weight at u_0 … u_2M
    double topWeight = 0.0;      // the same at u = ln 30
};

MaxwellianRule maxwellianRule(double logEnergyStep)
{
    const double lowestU = std::log(0.01), highestU = std::log(30.0); // the per-texel rule's limits
    constexpr double kLongestStep = 1.0 / 32.0;
    MaxwellianRule rule;
    rule.lowestU = lowestU;
    rule.substeps = logEnergyStep > 0.0 ? static_cast<int>(std::ceil(logEnergyStep / kLongestStep)) : 1;
    const double h = logEnergyStep > 0.0 ? logEnergyStep / rule.substeps : kLongestStep;
    rule.step = h;
    const int simpsonIntervals = 2 * static_cast<int>(std::floor((highestU - lowestU) / (2.0 * h)));
    std::vector<double> quadrature(static_cast<size_t>(simpsonIntervals) + 1);
    for (int n = 0; n <= simpsonIntervals; ++n)
        quadrature[static_cast<size_t>(n)] = (n == 0 || n == simpsonIntervals ? 1.0 : (n % 2 ? 4.0 : 2.0)) * h / 3.0;

    // The remainder [t, t + R]: Lagrange weights of the nodes t − 2h, t − h, t, t + R (in units of h
    // from t), integrated by 3-point Gauss–Legendre, exact for the cubic basis polynomials.
    const double remainder = (highestU - lowestU) / h - simpsonIntervals; // R/h, in [0, 2)
    const double nodes[4] = {-2.0, -1.0, 0.0, remainder};
    const double gaussPoint[3] = {-std::sqrt(0.6), 0.0, std::sqrt(0.6)}, gaussWeight[3] = {5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0};
    double tail[4] = {0.0, 0.0, 0.0, 0.0};
    for (int g = 0; g < 3; ++g) {
        const double t = 0.5 * remainder * (1.0 + gaussPoint[g]);
        for (int i = 0; i < 4; ++i) {
            double basis = 1.0;
            for (int k = 0; k < 4; ++k)
                if (k != i)
                    basis *= (t - nodes[k]) / (nodes[i] - nodes[k]);
            tail[i] += 0.5 * remainder * gaussWeight[g] * basis * h;
        }
    }
    for (int i = 0; i < 3; ++i)
        quadrature[static_cast<size_t>(simpsonIntervals - 2 + i)] += tail[i];

    const auto kernel = [](double u) {
        const double x = std::exp(u);
        return 0.5 * x * x * x * std::exp(-x);
    };
    rule.weights.resize(quadrature.size());
    for (size_t n = 0; n < quadrature.size(); ++n)
        rule.weights[n] = kernel(lowestU + static_cast<double>(n) * h) * quadrature[n];
    rule.topWeight = kernel(highestU) * tail[3];
    return rule;
}

void fillMaxwellianRows(const DepositionTableSpec& spec, DepositionTable& table)
{
    const MaxwellianRule rule = maxwellianRule(table.logEnergyStep);
    const int gridCount = (table.energyCount - 1) * rule.substeps + static_cast<int>(rule.weights.size());
    std::vector<double> gridMass(static_cast<size_t>(gridCount)), topMass(static_cast<size_t>(table.energyCount));
    for (int p = 0; p < gridCount; ++p)
        gridMass[static_cast<size_t>(p)] = characteristicMass(std::exp(table.minLogEnergy + rule.lowestU + p * rule.step));
    for (int j = 0; j < table.energyCount; ++j)
        topMass[static_cast<size_t>(j)] = characteristicMass(30.0 * std::exp(table.minLogEnergy + j * table.logEnergyStep));

    std::vector<double> mono(gridMass.size()), sum(static_cast<size_t>(table.energyCount));
    for (int i = 0; i < table.altitudeCount; ++i) {
        const double altitudeKm = spec.minAltitudeKm + i * spec.altitudeStepKm;
        const double density = massDensity(altitudeKm), shielding = shieldingMass(altitudeKm);
        for (size_t p = 0; p < mono.size(); ++p)
            mono[p] = monoenergeticDepositionPerEnergyFlux(density, shielding, gridMass[p]);
        for (int j = 0; j < table.energyCount; ++j)
            sum[static_cast<size_t>(j)] =
                rule.topWeight * monoenergeticDepositionPerEnergyFlux(density, shielding, topMass[static_cast<size_t>(j)]);
        // Node by node across all energies: each texel's sum keeps its order, the inner loop
        // vectorises over texels.
        for (size_t n = 0; n < rule.weights.size(); ++n)
            for (int j = 0; j < table.energyCount; ++j)
                sum[static_cast<size_t>(j)] += rule.weights[n] * mono[static_cast<size_t>(j) * rule.substeps + n];
        for (int j = 0; j < table.energyCount; ++j)
            table.decibels[static_cast<size_t>(j) * table.altitudeCount + i] =
                decibelsOf(sum[static_cast<size_t>(j)], spec.floorDecibels);
    }
}

void fillMonoenergeticRows(const DepositionTableSpec& spec, DepositionTable& table)
{
    for (int i = 0; i < table.altitudeCount; ++i) {
        const double altitudeKm = spec.minAltitudeKm + i * spec.altitudeStepKm;
        const double density = massDensity(altitudeKm), shielding = shieldingMass(altitudeKm);
        for (int j = 0; j < table.energyCount; ++j) {
            const double energyKeV = std::exp(table.minLogEnergy + j * table.logEnergyStep);
            table.decibels[static_cast<size_t>(j) * table.altitudeCount + i] = decibelsOf(
                depositionPerEnergyFlux(density, shielding, energyKeV, Spectrum::Monoenergetic), spec.floorDecibels);
        }
    }
}

} // namespace

DepositionTable buildDepositionTable(const DepositionTableSpec& spec)
{
    DepositionTable table;
    table.altitudeCount = altitudeCountOf(spec);
    table.energyCount = spec.energyCount;
    table.minAltitudeKm = spec.minAltitudeKm;
    table.altitudeStepKm = spec.altitudeStepKm;
    table.minLogEnergy = std::log(spec.minEnergyKeV);
    table.logEnergyStep = spec.energyCount > 1
                              ? (std::log(spec.maxEnergyKeV) - table.minLogEnergy) / (spec.energyCount - 1)
                              : 0.0;
    table.decibels.resize(static_cast<size_t>(table.altitudeCount) * table.energyCount);
    if (spec.spectrum == Spectrum::Maxwellian)
        fillMaxwellianRows(spec, table);
    else
        fillMonoenergeticRows(spec, table);
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

} // namespace aurorawall::components::aurora::physics
