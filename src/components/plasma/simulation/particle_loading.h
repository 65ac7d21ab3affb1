#pragma once
// Initial electrons on a periodic grid: a quiet start (evenly spaced, the same bits every time) and
// a random start (seeded, deterministic). Both give the macroparticle weight that makes the mean
// density `electronDensity` (m⁻³).
#include "components/plasma/simulation/particles.h"
#include "components/plasma/simulation/periodic_grid.h"

#include <cstdint>

namespace aurorawall::components::plasma::simulation {

// A displacement δx = amplitude · sin(2π mode x/L) along x of particles at x, L the box's length
// along x: a density perturbation δn/n = −(2π mode/L) · amplitude · cos(2π mode x/L) to first order.
struct Perturbation {
    int mode = 1;
    double amplitude = 0.0; // m
};

// `count` electrons evenly spaced along x (x_i = (i + 1/2) L/count), then displaced by the
// perturbation, all with velocity `drift` (m/s); y and z at the box's middle. For 1D runs.
Particles quietStart(const PeriodicGrid& grid, int count, double electronDensity, Perturbation perturbation,
                     glm::dvec3 drift);

// A cold 2D or 3D lattice: perCellPerAxis^dimension electrons per cell evenly spaced along each
// axis of the grid, then displaced along the diagonal unit vector d = (1, 1)/√2 (3D: (1, 1, 1)/√3) by
// amplitude · sin(k·x), k = 2π mode (1/L_x, 1/L_y[, 1/L_z]): a density wave δn/n = −|k| · amplitude ·
// cos(k·x) to first order, travelling along d on a square box (a cube). All at rest; in 2D z at the
// box's middle.
Particles diagonalWaveLattice(const PeriodicGrid& grid, int perCellPerAxis, double electronDensity,
                              Perturbation perturbation);

// A quiet Maxwellian along x: as quietStart, with x-velocities the normal quantiles
// thermalSpeed · √2 · erf⁻¹(2u − 1) at u = (r + 1/2)/count, r the bit-reversed index of the particle
// (Birdsall & Langdon 1991, §16-6: the reversal keeps positions and velocities uncorrelated);
// count a power of two.
Particles quietMaxwellian(const PeriodicGrid& grid, int count, double electronDensity, Perturbation perturbation,
                          double thermalSpeed);

// `count` electrons uniformly random in the box with Maxwellian velocities (thermal speed per
// component, m/s): uniform deviates from the 53 high bits of std::mt19937_64 (fully specified by
// the C++ standard) and normal ones by Box–Muller, so a seed gives the same bits on every platform.
Particles randomStart(const PeriodicGrid& grid, int count, double electronDensity, double thermalSpeed,
                      std::uint64_t seed);

} // namespace aurorawall::components::plasma::simulation
