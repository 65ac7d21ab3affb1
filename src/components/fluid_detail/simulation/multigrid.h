#pragma once
// Geometric multigrid for the periodic Poisson problem L p = f (Briggs, Henson & McCormick,
// "A Multigrid Tutorial", 2nd ed., SIAM 2000, chapters 3–4). See docs/fluid.md, "Pressure".
#include "components/fluid_detail/simulation/periodic_field.h"

#include <vector>

namespace aurorawall::components::fluid_detail::simulation {

struct MultigridSettings {
    int maxCycles = 20;       // V-cycles at most
    double tolerance = 1e-6;  // stop when rms(f − L p) ≤ tolerance · rms(f)
    int preSmoothing = 2;     // red-black Gauss–Seidel sweeps before the coarse-grid correction
    int postSmoothing = 2;    // and after
};

struct MultigridReport {
    // rms(f − L p): [0] for the initial guess, [k] after V-cycle k (f with its mean removed).
    std::vector<double> residualRms;
    double rhsRms = 0.0;
    bool converged = false;
    int cycles() const { return int(residualRms.size()) - 1; }
};

// Solves L p = f − mean(f), L the 5-point Laplacian on the periodic grid of p,
//   (L p)ᵢⱼ = (pᵢ₊₁ⱼ − 2pᵢⱼ + pᵢ₋₁ⱼ)/hx² + (pᵢⱼ₊₁ − 2pᵢⱼ + pᵢⱼ₋₁)/hy²,
// with V(ν₁,ν₂)-cycles (Briggs et al. ch. 3, "V-cycle scheme"): red-black Gauss–Seidel
// smoothing, full-weighting restriction, bilinear prolongation, the operator rediscretized on
// each coarser grid (2h), coarsening down to a grid 2 nodes thick that is solved directly.
// p is the initial guess and the result; its mean is set to zero (the periodic problem fixes p
// only up to a constant, and needs Σ f = 0, hence the mean removal). Needs nx, ny ≥ 2 powers
// of two and cells not far from square (hx/hy in [1/2, 2]) for the point smoother to work.
MultigridReport solvePoisson(PeriodicField& p, const PeriodicField& f, const MultigridSettings& settings);

} // namespace aurorawall::components::fluid_detail::simulation
