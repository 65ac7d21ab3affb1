// The FFT Poisson solver: exact (to rounding) for the 5-point Laplacian applied here stencil by
// stencil, in agreement with a multigrid solve run to round-off, mean handling, and bit-for-bit
// repeatable.
#include "components/fluid_detail/simulation/fft_poisson.h"
#include "physics/constants.h"
#include "components/fluid_detail/simulation/multigrid.h"
#include "flow_metrics.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <tuple>

namespace aurorawall::components::fluid_detail::simulation {
namespace {

// (L p)ᵢⱼ = (pᵢ₊₁ⱼ − 2pᵢⱼ + pᵢ₋₁ⱼ)/hx² + (pᵢⱼ₊₁ − 2pᵢⱼ + pᵢⱼ₋₁)/hy², stencil by stencil.
PeriodicField applyLaplacian(const PeriodicField& p)
{
    PeriodicField lp(p.nx, p.ny, p.hx, p.hy);
    for (int j = 0; j < p.ny; ++j)
        for (int i = 0; i < p.nx; ++i)
            lp(i, j) = (p(i + 1, j) - 2.0 * p(i, j) + p(i - 1, j)) / (p.hx * p.hx) +
                       (p(i, j + 1) - 2.0 * p(i, j) + p(i, j - 1)) / (p.hy * p.hy);
    return lp;
}

// Zero-mean values in [−½, ½) from the Numerical Recipes LCG: every wavenumber at once.
PeriodicField hashNoise(int nx, int ny, double hx, double hy, std::uint32_t state)
{
    PeriodicField f(nx, ny, hx, hy);
    for (double& q : f.values) {
        state = state * 1664525u + 1013904223u;
        q = double(state >> 8) / double(1u << 24) - 0.5;
    }
    f.subtractMean();
    return f;
}

double maxAbs(const PeriodicField& f)
{
    double m = 0.0;
    for (double q : f.values)
        m = std::max(m, std::abs(q));
    return m;
}

TEST(FftPoisson, RecoversAFieldFromItsDiscreteLaplacian)
{
    // p₀ of hash noise (the checkerboard and the Nyquist modes included), f = L p₀: the solve
    // must return p₀, on square cells and on cells with hx ≠ hy.
    for (const auto& [nx, ny, hx, hy] : {std::tuple{512, 128, 0.25, 0.25}, std::tuple{64, 256, 0.3, 0.2}, std::tuple{2, 4, 1.0, 1.0}}) {
        const PeriodicField exact = hashNoise(nx, ny, hx, hy, 99u);
        const PeriodicField f = applyLaplacian(exact);
        FftPoisson solver(nx, ny, hx, hy);
        PeriodicField p(nx, ny, hx, hy);
        solver.solve(p, f);
        const double error = maxAbsDifference(p, exact) / maxAbs(exact);
        const double residual = maxAbsDifference(applyLaplacian(p), f) / maxAbs(f);
        std::printf("  %4dx%-4d: max error / max |p| = %.2e, max residual / max |f| = %.2e\n", nx, ny, error, residual);
        EXPECT_LT(error, 1e-12);
        EXPECT_LT(residual, 1e-13);
    }
}

TEST(FftPoisson, AgreesWithMultigridSolvedToRoundOff)
{
    // A smooth right-hand side plus noise on the default strip; multigrid V-cycles until the
    // residual is 1e-13 of the right-hand side.
    const int nx = 512, ny = 128;
    const double hx = 0.25, hy = 0.25;
    PeriodicField f = hashNoise(nx, ny, hx, hy, 5u);
    for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i)
            f(i, j) += std::sin(2 * aurorawall::physics::kPi * 3 * i / nx) * std::cos(2 * aurorawall::physics::kPi * j / ny);
    PeriodicField multigrid(nx, ny, hx, hy);
    ASSERT_TRUE(solvePoisson(multigrid, f, {60, 1e-13, 2, 2}).converged);
    PeriodicField fft(nx, ny, hx, hy);
    FftPoisson(nx, ny, hx, hy).solve(fft, f);
    const double difference = maxAbsDifference(fft, multigrid) / maxAbs(multigrid);
    std::printf("  max |p_fft - p_multigrid| / max |p| = %.2e\n", difference);
    EXPECT_LT(difference, 1e-11);
}

TEST(FftPoisson, IgnoresTheMeanOfTheRhsAndReturnsZeroMean)
{
    const PeriodicField exact = hashNoise(64, 64, 1.0, 1.0, 3u);
    PeriodicField f = applyLaplacian(exact);
    for (double& q : f.values)
        q += 3.0;
    PeriodicField p(64, 64, 1.0, 1.0);
    std::fill(p.values.begin(), p.values.end(), 7.0); // old values are not used
    FftPoisson(64, 64, 1.0, 1.0).solve(p, f);
    EXPECT_NEAR(p.mean(), 0.0, 1e-15);
    EXPECT_LT(maxAbsDifference(p, exact), 1e-12);
}

TEST(FftPoisson, IsBitForBitRepeatable)
{
    // The same rhs solved twice by one solver and once by a second solver of the same grid.
    const PeriodicField f = hashNoise(512, 128, 0.25, 0.25, 17u);
    FftPoisson first(512, 128, 0.25, 0.25);
    FftPoisson second(512, 128, 0.25, 0.25);
    PeriodicField a(512, 128, 0.25, 0.25), b = a, c = a;
    first.solve(a, f);
    first.solve(b, f);
    second.solve(c, f);
    const std::size_t bytes = a.values.size() * sizeof(double);
    EXPECT_EQ(std::memcmp(a.values.data(), b.values.data(), bytes), 0);
    EXPECT_EQ(std::memcmp(a.values.data(), c.values.data(), bytes), 0);
    EXPECT_GT(maxAbs(a), 0.0);
}

TEST(FftPoisson, RejectsBadGrids)
{
    EXPECT_THROW(FftPoisson(48, 64, 1.0, 1.0), std::invalid_argument);
    EXPECT_THROW(FftPoisson(64, 64, 0.0, 1.0), std::invalid_argument);
    FftPoisson solver(64, 32, 1.0, 1.0);
    PeriodicField p(64, 32, 1.0, 1.0);
    PeriodicField wrong(64, 32, 1.0, 0.5);
    EXPECT_THROW(solver.solve(p, wrong), std::invalid_argument);
    EXPECT_THROW(solver.solve(wrong, p), std::invalid_argument);
}

} // namespace
} // namespace aurorawall::components::fluid_detail::simulation
