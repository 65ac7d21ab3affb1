#pragma once
// The aurora tables the per-curtain emission rows are built from (emission_table.h): deposition over altitude ×
// ln energy in decibels, and the per-altitude line yields. See docs/aurora-physics.md, "Tables".
#include "components/aurora/physics/lazarev.h"

#include <glm/glm.hpp>
#include <vector>

namespace aurorawall::components::aurora::physics {

struct DepositionTableSpec {
    double minAltitudeKm = 60.0;
    double maxAltitudeKm = 600.0;
    double altitudeStepKm = 0.5;  // the altitude count is round((max − min)/step) + 1
    double minEnergyKeV = 0.5;
    double maxEnergyKeV = 50.0;
    int energyCount = 128;        // log-spaced, both ends included
    Spectrum spectrum = Spectrum::Monoenergetic;
    double floorDecibels = -200.0;
};

struct DepositionTable {
    int altitudeCount = 0;
    int energyCount = 0;
    double minAltitudeKm = 0.0;
    double altitudeStepKm = 0.0;
    double minLogEnergy = 0.0;    // ln(keV)
    double logEnergyStep = 0.0;
    // 10·log10(rate), rate in keV cm⁻³ s⁻¹ per erg cm⁻² s⁻¹ (depositionPerEnergyFlux·kKeVPerErg),
    // floored at the spec's floorDecibels; row-major, one row per energy: [j·altitudeCount + i].
    std::vector<float> decibels;

    // (z_0 km, Δz km, ln E_0, Δln E) and (altitude count, energy count), as depositionTexCoord takes them.
    glm::vec4 axes() const;
    glm::vec2 size() const;
};

DepositionTable buildDepositionTable(const DepositionTableSpec& spec);

// The rate the table stores at (z, E), in double: depositionPerEnergyFlux(z, E, spectrum)·kKeVPerErg.
double depositionRate(double altitudeKm, double energyKeV, Spectrum spectrum);

// GL_LINEAR along one axis of n texels with clamp-to-edge (OpenGL 4.6 §8.14.2), for CPU twins of table
// lookups: texel coordinate x = u·n − 1/2, neighbours floor(x) and floor(x) + 1 clamped to [0, n − 1],
// weight fract(x).
struct LinearTaps {
    int i0, i1;
    float weight;
};
LinearTaps linearTaps(float u, int n);

// The table's lookup at (z, E), as a GPU texture would filter it: the shared texture-coordinate mapping in
// float, GL_LINEAR filtering of the float texels with clamp-to-edge (OpenGL 4.6 §8.14.2), then
// decibelsToValue in float. The lookup error of docs/aurora-physics.md, "Tables".
float sampleDepositionTable(const DepositionTable& table, float altitudeKm, float energyKeV);

// Per-altitude yields, photons per keV deposited, of the four emissions (aurora/emission.h) on the
// deposition table's altitude axis: RGBA32F texture of altitudeCount × 1, texel i = line yields at z_i.
std::vector<glm::vec4> buildLineYieldTable(const DepositionTableSpec& spec);

} // namespace aurorawall::components::aurora::physics
