#include "components/plasma/simulation/fft_poisson_solver.h"

#include "physics/constants.h"
#include "components/plasma/simulation/plasma_parameters.h"

#include <fftw3.h>

#include <algorithm>
#include <cmath>
#include <new>
#include <stdexcept>

namespace aurorawall::components::plasma::simulation {

// The aligned buffers, the two plans on them, and −1/(ε₀ λ N) per stored mode (N, the node count,
// undoes FFTW's unnormalised inverse).
struct FftPoissonSolver::Plans {
    std::size_t nodes = 0;
    double* field = nullptr;          // nz × ny × nx, x fastest like PeriodicGrid::index
    fftw_complex* spectrum = nullptr; // nz × ny × (nx/2 + 1): the real-to-complex half spectrum
    fftw_plan forward = nullptr;
    fftw_plan backward = nullptr;
    std::vector<double> potentialPerCharge;

    ~Plans()
    {
        if (forward) fftw_destroy_plan(forward);
        if (backward) fftw_destroy_plan(backward);
        fftw_free(spectrum);
        fftw_free(field);
    }
};

FftPoissonSolver::FftPoissonSolver(const PeriodicGrid& grid) : plans_(std::make_unique<Plans>())
{
    Plans& p = *plans_;
    const int nx = grid.cells[0], ny = grid.cells[1], nz = grid.cells[2];
    const int half = nx / 2 + 1;
    const std::size_t modes = std::size_t(nz) * ny * half;
    p.nodes = grid.nodeCount();
    p.field = fftw_alloc_real(p.nodes);
    p.spectrum = fftw_alloc_complex(modes);
    if (!p.field || !p.spectrum)
        throw std::bad_alloc();
    // Axes of one cell are transforms of length 1 (the identity), so one rank-3 plan serves 1D–3D.
    const int shape[3] = {nz, ny, nx};
    p.forward = fftw_plan_dft_r2c(3, shape, p.field, p.spectrum, FFTW_ESTIMATE);
    p.backward = fftw_plan_dft_c2r(3, shape, p.spectrum, p.field, FFTW_ESTIMATE);
    if (!p.forward || !p.backward)
        throw std::runtime_error("FftPoissonSolver: FFTW could not plan the transform");

    const auto term = [](int k, int n, double h) {
        const double s = std::sin(physics::kPi * k / n);
        return 4.0 * s * s / (h * h);
    };
    p.potentialPerCharge.resize(modes);
    for (int kz = 0; kz < nz; ++kz)
        for (int ky = 0; ky < ny; ++ky)
            for (int kx = 0; kx < half; ++kx) {
                const double lambda = -(term(kx, nx, grid.spacing[0]) + term(ky, ny, grid.spacing[1]) +
                                        term(kz, nz, grid.spacing[2]));
                p.potentialPerCharge[(std::size_t(kz) * ny + ky) * half + kx] =
                    kx == 0 && ky == 0 && kz == 0 ? 0.0 : -1.0 / (kVacuumPermittivity * lambda * double(p.nodes));
            }
}

FftPoissonSolver::~FftPoissonSolver() = default;
FftPoissonSolver::FftPoissonSolver(FftPoissonSolver&&) noexcept = default;
FftPoissonSolver& FftPoissonSolver::operator=(FftPoissonSolver&&) noexcept = default;

std::vector<double> FftPoissonSolver::solve(const std::vector<double>& chargeDensity) const
{
    const Plans& p = *plans_;
    if (chargeDensity.size() != p.nodes)
        throw std::invalid_argument("FftPoissonSolver::solve: the charge density is not on the solver's grid");
    std::copy(chargeDensity.begin(), chargeDensity.end(), p.field);
    fftw_execute(p.forward);
    for (std::size_t k = 0; k < p.potentialPerCharge.size(); ++k) {
        p.spectrum[k][0] *= p.potentialPerCharge[k];
        p.spectrum[k][1] *= p.potentialPerCharge[k];
    }
    fftw_execute(p.backward);
    return std::vector<double>(p.field, p.field + p.nodes);
}

} // namespace aurorawall::components::plasma::simulation
