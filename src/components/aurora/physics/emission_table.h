#pragma once
// The line emission of one curtain's electrons over altitude, as the renderer reads it
// (shaders/components/aurora/curtain_emission.glsl): a curtain's electron energy is fixed within a frame, so
// each frame one row per curtain holds the emission at nodes along the altitude axis, and a ray's sample costs
// one filtered read instead of the deposition and line-yield reads and the sum over the lines.
// See docs/aurora-physics.md, "Tables".
#include "components/aurora/physics/deposition_table.h"
#include "components/aurora/physics/emission.h"

#include <glm/glm.hpp>

#include <array>
#include <vector>

namespace aurorawall::components::aurora::physics {

// The rows' nodes are this many times finer than the deposition table's altitudes: the texture interpolates
// the emission linearly, where the table interpolates the deposition in decibels (exact for an exponential),
// and the finer nodes keep the difference below 1% wherever the emission exceeds 1e-3 of its peak.
constexpr int kEmissionSubdivisions = 2;

struct EmissionTables {
    DepositionTable deposition;
    std::vector<glm::vec4> lineYields;          // on the deposition table's altitude axis (buildLineYieldTable)
    std::array<glm::dvec3, kLineCount> lineRgb; // linear sRGB (cd/m²) of one rayleigh of each line

    // Node count (altitudeCount − 1)·kEmissionSubdivisions + 1; node k lies at z_0 + k·nodeSpacingKm().
    int nodeCount() const;
    double nodeSpacingKm() const;
    // The uniform uCurtainEmissionAxes: (z_0 km, node spacing km, node count).
    glm::vec3 axes() const;
};

EmissionTables buildEmissionTables(const DepositionTableSpec& spec);

// The row for electrons of energy E (keV): linear sRGB per km of path per erg cm⁻² s⁻¹ at each node,
//   0.1 · 10^(dB(z, E)/10) · Σ_lines yield(z) · rgb,
// (1 photon cm⁻³ s⁻¹ over 1 km is a column of 0.1 R) with the deposition's decibels linear between the
// table's altitudes and ln-energies (clamped at its ends) and the yields linear between altitudes.
// Writes nodeCount() RGBA texels (A = 0) from out.
void emissionRow(const EmissionTables& tables, double energyKeV, float* out);

// What the texture returns for altitude z (km) from a row: the shared coordinate (emissionTexCoord) in float,
// then GL_LINEAR between nodes with clamp-to-edge.
glm::vec3 sampleEmissionRow(const EmissionTables& tables, const std::vector<float>& row, float altitudeKm);

} // namespace aurorawall::components::aurora::physics
