#pragma once
// The (2·dimension + 1)-point Laplacian on a periodic grid and the residual of Poisson's equation
// ∇²φ = −ρ/ε₀ (Birdsall & Langdon 1991, §2-5).
#include "components/plasma/simulation/periodic_grid.h"

#include <vector>

namespace aurorawall::components::plasma::simulation {

// (∇²φ) at every node: Σ_d (φ[+d] − 2φ + φ[−d])/Δ_d² (V/m²).
std::vector<double> laplacian(const PeriodicGrid& grid, const std::vector<double>& potential);

// ‖∇²φ + ρ̃/ε₀‖₂ / ‖ρ̃/ε₀‖₂, ρ̃ = ρ − mean(ρ) (the part a periodic potential can hold); 0 for ρ̃ = 0.
double poissonResidual(const PeriodicGrid& grid, const std::vector<double>& chargeDensity,
                       const std::vector<double>& potential);

} // namespace aurorawall::components::plasma::simulation
