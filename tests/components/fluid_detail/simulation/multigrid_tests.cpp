// The periodic multigrid Poisson solver: V-cycle convergence factor, second-order accuracy on a
// manufactured problem, and the checkerboard mode that plain Jacobi cannot remove.
#include "physics/constants.h"
#include "components/fluid_detail/simulation/multigrid.h"
#include "flow_metrics.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <tuple>

namespace aurorawall::components::fluid_detail::simulation {
namespace {

// φ = sin(2πx/Lx) cos(4πy/Ly) + ½ cos(6πx/Lx + 0.3) sin(2πy/Ly + 1): zero mean, periodic.
double phi(double x, double y, double lx, double ly)
{
    return std::sin(2 * aurorawall::physics::kPi * x / lx) * std::cos(4 * aurorawall::physics::kPi * y / ly) + 0.5 * std::cos(6 * aurorawall::physics::kPi * x / lx + 0.3) * std::sin(2 * aurorawall::physics::kPi * y / ly + 1.0);
}

// Its Laplacian, analytically.
double laplacianOfPhi(double x, double y, double lx, double ly)
{
    const double kx1 = 2 * aurorawall::physics::kPi / lx, ky1 = 4 * aurorawall::physics::kPi / ly, kx2 = 6 * aurorawall::physics::kPi / lx, ky2 = 2 * aurorawall::physics::kPi / ly;
    return -(kx1 * kx1 + ky1 * ky1) * std::sin(kx1 * x) * std::cos(ky1 * y) -
           (kx2 * kx2 + ky2 * ky2) * 0.5 * std::cos(kx2 * x + 0.3) * std::sin(ky2 * y + 1.0);
}

struct Manufactured {
    PeriodicField exact;
    PeriodicField rhs;
};

Manufactured manufactured(int nx, int ny, double lx, double ly)
{
    Manufactured m{PeriodicField(nx, ny, lx / nx, ly / ny), PeriodicField(nx, ny, lx / nx, ly / ny)};
    for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i) {
            const double x = (i + 0.5) * lx / nx, y = (j + 0.5) * ly / ny;
            m.exact(i, j) = phi(x, y, lx, ly);
            m.rhs(i, j) = laplacianOfPhi(x, y, lx, ly);
        }
    return m;
}

// Every V-cycle cuts the residual by at least 10× until it reaches round-off.
void expectTenfoldPerCycle(const MultigridReport& report)
{
    ASSERT_TRUE(report.converged);
    for (int k = 1; k <= report.cycles(); ++k) {
        if (report.residualRms[k - 1] < 1e-10 * report.rhsRms)
            break;
        const double factor = report.residualRms[k] / report.residualRms[k - 1];
        SCOPED_TRACE("cycle " + std::to_string(k));
        EXPECT_LE(factor, 0.1);
        std::printf("  cycle %2d: residual %.3e (factor %.4f)\n", k, report.residualRms[k] / report.rhsRms, factor);
    }
}

TEST(Multigrid, ResidualDropsTenfoldPerVCycleOnTheManufacturedProblem)
{
    for (const auto& [nx, ny, lx, ly] : {std::tuple{128, 128, 1.0, 1.0}, std::tuple{512, 128, 128.0, 32.0}}) {
        SCOPED_TRACE(std::to_string(nx) + "x" + std::to_string(ny));
        const Manufactured m = manufactured(nx, ny, lx, ly);
        PeriodicField p(nx, ny, lx / nx, ly / ny);
        const MultigridReport report = solvePoisson(p, m.rhs, {30, 1e-13, 2, 2});
        expectTenfoldPerCycle(report);
    }
}

TEST(Multigrid, ResidualDropsTenfoldPerVCycleOnHashNoise)
{
    // All frequencies at once, from an integer hash (no platform-dependent random numbers).
    PeriodicField f(256, 64, 0.25, 0.25);
    std::uint32_t state = 12345u;
    for (double& q : f.values) {
        state = state * 1664525u + 1013904223u; // Numerical Recipes LCG
        q = double(state >> 8) / double(1u << 24) - 0.5;
    }
    PeriodicField p(256, 64, 0.25, 0.25);
    expectTenfoldPerCycle(solvePoisson(p, f, {30, 1e-13, 2, 2}));
}

TEST(Multigrid, SolutionIsSecondOrderAccurate)
{
    double previous = 0.0;
    for (int n : {32, 64, 128, 256}) {
        const Manufactured m = manufactured(n, n, 1.0, 1.0);
        PeriodicField p(n, n, 1.0 / n, 1.0 / n);
        ASSERT_TRUE(solvePoisson(p, m.rhs, {30, 1e-12, 2, 2}).converged);
        const double error = maxAbsDifference(p, m.exact);
        std::printf("  n = %3d: max error %.3e%s", n, error, previous > 0 ? "" : "\n");
        if (previous > 0) {
            std::printf(" (ratio %.3f)\n", previous / error);
            EXPECT_NEAR(previous / error, 4.0, 0.2);
        }
        previous = error;
    }
}

TEST(Multigrid, CheckerboardModeConverges)
{
    // (−1)^(i+j) is an eigenvector of L with eigenvalue −4/hx² − 4/hy², and of the Jacobi
    // iteration matrix with eigenvalue −1: plain Jacobi flips its sign forever.
    for (const auto& [nx, ny, hx, hy] : {std::tuple{64, 64, 1.0, 1.0}, std::tuple{128, 32, 0.25, 0.5}}) {
        PeriodicField f(nx, ny, hx, hy);
        PeriodicField exact(nx, ny, hx, hy);
        for (int j = 0; j < ny; ++j)
            for (int i = 0; i < nx; ++i) {
                f(i, j) = (i + j) % 2 == 0 ? 1.0 : -1.0;
                exact(i, j) = f(i, j) / (-4.0 / (hx * hx) - 4.0 / (hy * hy));
            }
        PeriodicField p(nx, ny, hx, hy);
        const MultigridReport report = solvePoisson(p, f, {30, 1e-12, 2, 2});
        EXPECT_TRUE(report.converged);
        EXPECT_LE(report.cycles(), 2);
        EXPECT_LT(maxAbsDifference(p, exact), 1e-12);
    }
}

TEST(Multigrid, MeanOfRhsIsIgnoredAndSolutionHasZeroMean)
{
    const Manufactured m = manufactured(64, 64, 1.0, 1.0);
    PeriodicField shifted = m.rhs;
    for (double& q : shifted.values)
        q += 3.0;
    PeriodicField p(64, 64, 1.0 / 64, 1.0 / 64);
    for (double& q : p.values)
        q = 7.0; // an initial guess far off in the null space
    ASSERT_TRUE(solvePoisson(p, shifted, {30, 1e-12, 2, 2}).converged);
    EXPECT_NEAR(p.mean(), 0.0, 1e-14);
    PeriodicField reference(64, 64, 1.0 / 64, 1.0 / 64);
    ASSERT_TRUE(solvePoisson(reference, m.rhs, {30, 1e-12, 2, 2}).converged);
    EXPECT_LT(maxAbsDifference(p, reference), 1e-10);
}

TEST(Multigrid, RejectsMismatchedGridsAndLongCells)
{
    PeriodicField p(64, 64, 1.0, 1.0);
    PeriodicField f(64, 32, 1.0, 1.0);
    EXPECT_THROW(solvePoisson(p, f, {}), std::invalid_argument);
    PeriodicField q(64, 64, 1.0, 3.0);
    EXPECT_THROW(solvePoisson(q, q, {}), std::invalid_argument);
    EXPECT_THROW(PeriodicField(48, 64, 1.0, 1.0), std::invalid_argument);
}

} // namespace
} // namespace aurorawall::components::fluid_detail::simulation
