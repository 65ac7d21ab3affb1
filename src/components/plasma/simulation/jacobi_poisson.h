#pragma once
// Plain Jacobi sweeps for ∇²φ = −ρ/ε₀ on a periodic grid: a baseline, not a solver. Each sweep sets
//   φ ← (Σ_d (φ[+d] + φ[−d])/Δ_d² + ρ̃/ε₀) / Σ_d (2/Δ_d²),   ρ̃ = ρ − mean(ρ).
// Its iteration matrix has eigenvalues μ(k) = Σ_d cos(2π k_d/n_d)/Δ_d² / Σ_d 1/Δ_d²: 1 for the mean
// mode, which it never changes, and −1 for the checkerboard (−1)^(i+j+k) when every n_d is even,
// which it flips every sweep and never damps. So on an even periodic grid it never converges, and
// the smooth modes, μ = 1 − O((kΔ)²), decay slowly: on 64³, 20 sweeps remove only about 3% of the
// longest wave.
#include "components/plasma/simulation/periodic_grid.h"

#include <vector>

namespace aurorawall::components::plasma::simulation {

// `sweeps` Jacobi sweeps on `potential` (V, updated in place) for the charge density (C/m³).
void jacobiSweeps(const PeriodicGrid& grid, const std::vector<double>& chargeDensity, std::vector<double>& potential,
                  int sweeps);

} // namespace aurorawall::components::plasma::simulation
