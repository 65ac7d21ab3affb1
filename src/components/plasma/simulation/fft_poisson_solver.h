#pragma once
// Poisson's equation ∇²φ = −ρ/ε₀ on a periodic grid, solved exactly by the discrete Fourier
// transform (FFTW). The Fourier modes exp(2πi Σ_d k_d i_d/n_d) are the eigenvectors of the
// (2·dimension + 1)-point Laplacian with eigenvalues λ(k) = −Σ_d (4/Δ_d²) sin²(π k_d/n_d), so
// φ̂ = −ρ̂/(ε₀ λ) solves the discrete equation to rounding. The mean mode (λ = 0) is where the
// periodic problem has no solution unless Σρ = 0 and no unique one even then: its ρ̂ is dropped (the
// neutralising background) and its φ̂ pinned to 0 (zero mean potential).
//
// The plans are made with FFTW_ESTIMATE, which depends only on the grid and the build, so two runs
// (or two ranks) execute the same arithmetic and get the same bits. FFTW's planner is not
// thread-safe: make solvers from one thread.
#include "components/plasma/simulation/periodic_grid.h"

#include <memory>
#include <vector>

namespace aurorawall::components::plasma::simulation {

class FftPoissonSolver {
public:
    explicit FftPoissonSolver(const PeriodicGrid& grid);
    ~FftPoissonSolver();
    FftPoissonSolver(FftPoissonSolver&&) noexcept;
    FftPoissonSolver& operator=(FftPoissonSolver&&) noexcept;

    // The zero-mean potential (V) of the charge density (C/m³) minus its mean, both with
    // grid.nodeCount() values (std::invalid_argument otherwise).
    std::vector<double> solve(const std::vector<double>& chargeDensity) const;

private:
    struct Plans;
    std::unique_ptr<Plans> plans_;
};

} // namespace aurorawall::components::plasma::simulation
