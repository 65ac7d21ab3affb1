#include "components/fluid_detail/simulation/fft_poisson.h"

#include "physics/constants.h"

#include <fftw3.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <new>
#include <stdexcept>
#include <string>

namespace aurorawall::components::fluid_detail::simulation {

// The buffers (fftw_malloc: aligned, so the plans' SIMD code applies to them on every call), the
// two plans on them, and 1/(λ N) per stored mode (N = nx·ny undoes FFTW's unnormalized inverse).
struct FftPoisson::Plans {
    int nx = 0;
    int ny = 0;
    double hx = 0.0;
    double hy = 0.0;
    double* field = nullptr;         // ny × nx, row-major like PeriodicField::values
    fftw_complex* spectrum = nullptr; // ny × (nx/2 + 1): the real-to-complex half spectrum
    fftw_plan forward = nullptr;
    fftw_plan backward = nullptr;
    std::vector<double> inverseEigenvalue;

    ~Plans()
    {
        if (forward) fftw_destroy_plan(forward);
        if (backward) fftw_destroy_plan(backward);
        fftw_free(spectrum);
        fftw_free(field);
    }
};

FftPoisson::FftPoisson(int nx, int ny, double hx, double hy) : plans_(std::make_unique<Plans>())
{
    if (!isPowerOfTwo(nx) || !isPowerOfTwo(ny) || nx < 2 || ny < 2 || !(hx > 0.0) || !(hy > 0.0))
        throw std::invalid_argument("FftPoisson: needs nx, ny >= 2 powers of two and hx, hy > 0");
    Plans& p = *plans_;
    p.nx = nx;
    p.ny = ny;
    p.hx = hx;
    p.hy = hy;
    const int half = nx / 2 + 1;
    const std::size_t modes = std::size_t(ny) * half;
    p.field = fftw_alloc_real(std::size_t(nx) * ny);
    p.spectrum = fftw_alloc_complex(modes);
    if (!p.field || !p.spectrum)
        throw std::bad_alloc();
    // FFTW_DESTROY_INPUT (the default of complex-to-real plans) lets the inverse overwrite the
    // spectrum, which solve rebuilds every call anyway.
    p.forward = fftw_plan_dft_r2c_2d(ny, nx, p.field, p.spectrum, FFTW_ESTIMATE);
    p.backward = fftw_plan_dft_c2r_2d(ny, nx, p.spectrum, p.field, FFTW_ESTIMATE);
    if (!p.forward || !p.backward)
        throw std::runtime_error("FftPoisson: FFTW could not plan a " + std::to_string(nx) + "x" + std::to_string(ny) + " transform");

    p.inverseEigenvalue.resize(modes);
    const double n = double(nx) * double(ny);
    for (int ky = 0; ky < ny; ++ky) {
        const double sy = std::sin(physics::kPi * ky / ny);
        for (int kx = 0; kx < half; ++kx) {
            const double sx = std::sin(physics::kPi * kx / nx);
            const double lambda = -4.0 * sx * sx / (hx * hx) - 4.0 * sy * sy / (hy * hy);
            p.inverseEigenvalue[std::size_t(ky) * half + kx] = kx == 0 && ky == 0 ? 0.0 : 1.0 / (lambda * n);
        }
    }
}

FftPoisson::~FftPoisson() = default;
FftPoisson::FftPoisson(FftPoisson&&) noexcept = default;
FftPoisson& FftPoisson::operator=(FftPoisson&&) noexcept = default;

void FftPoisson::solve(PeriodicField& p, const PeriodicField& f)
{
    const Plans& s = *plans_;
    const auto onGrid = [&s](const PeriodicField& q) { return q.nx == s.nx && q.ny == s.ny && q.hx == s.hx && q.hy == s.hy; };
    if (!onGrid(p) || !onGrid(f))
        throw std::invalid_argument("FftPoisson::solve: p and f must have the solver's grid");
    std::copy(f.values.begin(), f.values.end(), s.field);
    fftw_execute(s.forward);
    for (std::size_t k = 0; k < s.inverseEigenvalue.size(); ++k) {
        s.spectrum[k][0] *= s.inverseEigenvalue[k];
        s.spectrum[k][1] *= s.inverseEigenvalue[k];
    }
    fftw_execute(s.backward);
    std::copy(s.field, s.field + p.values.size(), p.values.begin());
}

} // namespace aurorawall::components::fluid_detail::simulation
