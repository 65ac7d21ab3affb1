#pragma once
// A periodic grid of nodes in 1, 2 or 3 dimensions. Node (i, j, k) sits at (i Δx, j Δy, k Δz); the
// box is cells × spacing along each axis and wraps around. Axes beyond `dimension` have one cell of
// 1 m, so a 1D charge density is still in C/m³ (per m² of the sheets the particles stand for).
#include <glm/vec3.hpp>

#include <array>
#include <cstddef>

namespace aurorawall::components::plasma::simulation {

struct PeriodicGrid {
    // dimension 1–3; cells ≥ 1 and spacing > 0 (m) for each axis below dimension. Throws
    // std::invalid_argument otherwise.
    PeriodicGrid(int dimension, std::array<int, 3> cells, std::array<double, 3> spacing);

    int dimension;
    std::array<int, 3> cells;      // 1 beyond dimension
    std::array<double, 3> spacing; // m; 1 beyond dimension

    std::size_t nodeCount() const { return std::size_t(cells[0]) * cells[1] * cells[2]; }
    // Row-major with x fastest: i + nx (j + ny k), each wrapped into [0, n).
    std::size_t index(int i, int j, int k) const;
    double cellVolume() const { return spacing[0] * spacing[1] * spacing[2]; } // m³
    glm::dvec3 boxLength() const;                                               // m
};

} // namespace aurorawall::components::plasma::simulation
