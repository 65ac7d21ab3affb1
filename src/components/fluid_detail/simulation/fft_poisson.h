#pragma once
// The periodic Poisson problem L p = f solved exactly by the discrete Fourier transform (FFTW).
// See docs/fluid.md, "Pressure: FFT".
#include "components/fluid_detail/simulation/periodic_field.h"

#include <memory>
#include <vector>

namespace aurorawall::components::fluid_detail::simulation {

// On the doubly periodic grid the Fourier modes exp(2πi (kx i/nx + ky j/ny)) are the eigenvectors
// of the 5-point Laplacian L (the divergence of the MAC face gradient) with eigenvalues
//   λ(kx, ky) = −(4/hx²) sin²(π kx/nx) − (4/hy²) sin²(π ky/ny),
// so p̂ = f̂/λ solves L p = f to rounding; the mean mode (λ = 0) is pinned to p̂ = 0, which drops
// the mean of f and gives p zero mean, as solvePoisson does. Double precision: the fields are
// double, and the projection should leave a divergence at double rounding (a float transform
// would stop at a relative 1e-7, no better than the multigrid's tolerance).
//
// The FFTW plans are made once, here, with FFTW_ESTIMATE: its plan depends only on the grid size,
// the library build and the CPU's instruction set, so every rank running the same binary on the
// same kind of CPU executes the same arithmetic and gets the same bits. FFTW_MEASURE picks the
// fastest of several plans by timing them, so two runs, or two ranks, could pick different plans
// and round differently. FFTW's planner is not thread-safe: construct solvers from one thread.
class FftPoisson {
public:
    // nx, ny powers of two ≥ 2 (like PeriodicField), hx, hy > 0 (km). Throws std::invalid_argument.
    FftPoisson(int nx, int ny, double hx, double hy);
    ~FftPoisson();
    FftPoisson(FftPoisson&&) noexcept;
    FftPoisson& operator=(FftPoisson&&) noexcept;

    // p ← the zero-mean solution of L p = f − mean(f). p and f must have this solver's grid
    // (std::invalid_argument otherwise); p's old values are not used.
    void solve(PeriodicField& p, const PeriodicField& f);

private:
    struct Plans;
    std::unique_ptr<Plans> plans_;
};

} // namespace aurorawall::components::fluid_detail::simulation
