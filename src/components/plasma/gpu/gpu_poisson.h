#pragma once
// Poisson's equation ∇²φ = −ρ/ε₀ on a periodic grid solved on the GPU, in float, by fixed numbers
// of sweeps of shaders/components/plasma/poisson_sweep.comp on the (2·dimension + 1)-point
// Laplacian of FftPoissonSolver. Deterministic: no atomics and no reductions, so the same source
// gives the same bits. Needs a current GL 4.5 context.
//
// Jacobi: the baseline of real-time GPU particle-in-cell codes. Its sweep multiplies the Fourier
// mode k of the error by μ(k) = Σ_d cos(2π k_d/n_d)/Δ_d² / Σ_d 1/Δ_d² (jacobi_poisson.h): the
// checkerboard (μ = −1 on an even grid) is never damped and the longest wave barely.
// Red-black SOR: successive over-relaxation with the nodes ordered red ((i + j + k) even) then black.
// That ordering is consistent (Young 1971, "Iterative Solution of Large Linear Systems", ch. 6), so
// the best ω and its rate follow from the Jacobi radius μ₁ of the longest non-constant wave:
// ω = 2/(1 + √(1 − μ₁²)), the error shrinking by about ω − 1 per sweep (one red and one black
// half-sweep). Needs an even number of cells along each axis of the dimension.
//
// Multigrid: geometric V-cycles, red-black Gauss–Seidel (ω = 1) smoothing, kSmoothingSweeps before and
// after the correction, the residual restricted by full weighting to the grid with half the cells
// along each axis of the dimension (twice the spacing), linear prolongation of the correction
// (Trottenberg, Oosterlee & Schüller 2001, "Multigrid", ch. 2), down to a grid with an odd cell
// count or 4 cells along some axis, solved there by kCoarsestSweeps Gauss–Seidel sweeps. Needs even
// cell counts, as red-black SOR.
//
// Every pass is a compute dispatch ordered by glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT); the
// coarse corrections start at 0 in the restriction pass, not by an upload from the CPU, which a
// driver that runs commands asynchronously may order before the previous V-cycle's shader accesses.
// Uploads and read-backs (setChargeDensity, clearPotential, potential) follow
// GL_BUFFER_UPDATE_BARRIER_BIT.
//
// None of them pins the mean of φ (Gauss–Seidel moves it, and on the coarse grids the restricted
// source sums to zero only up to rounding, the mean of the correction drifting by that much): the
// field E = −∇φ does not see the mean.
#include "components/plasma/simulation/periodic_grid.h"

#include <memory>
#include <string>
#include <vector>

namespace aurorawall::components::plasma::gpu {

enum class GpuPoissonMethod { Jacobi, RedBlackSor, Multigrid };

// ω = 2/(1 + √(1 − μ₁²)) for the grid, μ₁ the largest Jacobi factor μ(k) over k ≠ 0.
double sorOverRelaxation(const simulation::PeriodicGrid& grid);
// μ(k) of one Jacobi sweep for the mode with integer wave numbers k (cycles per box).
double jacobiFactor(const simulation::PeriodicGrid& grid, int kx, int ky, int kz);

class GpuPoisson {
public:
    // shaderDir holds components/plasma/. std::invalid_argument for red-black SOR on an odd cell count;
    // std::length_error for more grid nodes than one dispatch or one storage block of the current
    // context holds (gpu_limits.h).
    GpuPoisson(const simulation::PeriodicGrid& grid, GpuPoissonMethod method, const std::string& shaderDir);
    ~GpuPoisson();
    GpuPoisson(const GpuPoisson&) = delete;
    GpuPoisson& operator=(const GpuPoisson&) = delete;

    // The source ρ̃/ε₀ from a charge density (C/m³, nodeCount values; its mean removed in double).
    void setChargeDensity(const std::vector<double>& chargeDensity);
    // The source from the fixed-point deposit's node sums (GL buffer of int, in 2^-quantumBits
    // particles) of `particles` electrons of weight `weight`, on the GPU.
    void setChargeFromQuanta(unsigned quantaBuffer, std::size_t particles, double weight, int quantumBits);
    // φ = 0 everywhere.
    void clearPotential();
    // `sweeps` sweeps from the current potential (Jacobi sweeps, red-black SOR sweeps or V-cycles).
    void solve(int sweeps);
    // The multigrid's levels, the finest first (1 for the other methods).
    int levelCount() const { return int(levels_.size()); }

    double overRelaxation() const { return overRelaxation_; }
    // The GL storage buffer of φ (float, V, one per node).
    unsigned potentialBuffer() const { return buffers_[0]; }
    std::vector<double> potential() const;

    static constexpr int kSmoothingSweeps = 2;
    static constexpr int kCoarsestSweeps = 10;

private:
    struct Programs;
    struct Level {
        simulation::PeriodicGrid grid;
        unsigned potential = 0, source = 0, residual = 0; // GL buffers; level 0: in buffers_
    };
    void setGrid(int level) const;
    void redBlackSweep(int level, float overRelaxation) const;
    void vCycle(int level) const;
    simulation::PeriodicGrid grid_;
    GpuPoissonMethod method_;
    double overRelaxation_;
    std::unique_ptr<Programs> programs_;
    unsigned buffers_[3] = {}; // potential, source, Jacobi's second potential or the residual
    std::vector<Level> levels_;
};

} // namespace aurorawall::components::plasma::gpu
