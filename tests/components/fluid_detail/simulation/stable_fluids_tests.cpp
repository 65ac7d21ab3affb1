// Stable Fluids on the MAC grid: the projection leaves a discretely divergence-free field and is
// a Helmholtz–Hodge split; semi-Lagrangian advection moves things the right way and is monotone.
#include "components/fluid_detail/simulation/stable_fluids.h"
#include "physics/constants.h"
#include "flow_metrics.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <tuple>

namespace aurorawall::components::fluid_detail::simulation {
namespace {

// Values in [−½, ½) from the Numerical Recipes LCG (integer arithmetic: the same everywhere).
struct HashNoise {
    std::uint32_t state;
    double next()
    {
        state = state * 1664525u + 1013904223u;
        return double(state >> 8) / double(1u << 24) - 0.5;
    }
};

// A rough velocity field: a few sine modes (divergent and rotational) plus grid-scale noise.
MacVelocity roughVelocity(int nx, int ny, double h)
{
    MacVelocity vel{PeriodicField(nx, ny, h, h), PeriodicField(nx, ny, h, h)};
    const double lx = nx * h, ly = ny * h;
    HashNoise noise{7u};
    for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i) {
            const double x = i * h, y = (j + 0.5) * h;
            vel.u(i, j) = std::sin(2 * aurorawall::physics::kPi * x / lx) + 0.3 * std::cos(2 * aurorawall::physics::kPi * 3 * y / ly) + 0.2 * noise.next();
            vel.v(i, j) = std::cos(2 * aurorawall::physics::kPi * 2 * (x + 0.5 * h) / lx + 0.4) * std::sin(2 * aurorawall::physics::kPi * j * h / ly) + 0.2 * noise.next();
        }
    return vel;
}

TEST(Projection, LeavesDivergenceBelowOneMillionthOfTheVelocityGradient)
{
    MacVelocity vel = roughVelocity(256, 64, 0.5);
    const double before = divergenceRms(vel) / gradientRms(vel);
    PeriodicField phi(256, 64, 0.5, 0.5);
    const MultigridReport report = project(vel, phi, MultigridSettings{});
    const double after = divergenceRms(vel) / gradientRms(vel);
    std::printf("  rms div / rms |grad u|: %.3e before, %.3e after %d V-cycles\n", before, after, report.cycles());
    EXPECT_TRUE(report.converged);
    EXPECT_LE(after, 1e-6);
}

TEST(Projection, RemovesAGradientAndKeepsASolenoidalField)
{
    // u = ∇ψ (face differences of a cell-centred ψ) projects to zero; a shear flow u(y) is kept.
    const int nx = 128, ny = 64;
    const double h = 0.25;
    PeriodicField psi(nx, ny, h, h);
    for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i)
            psi(i, j) = std::sin(2 * aurorawall::physics::kPi * i / nx) * std::cos(2 * aurorawall::physics::kPi * 2 * j / ny) + 0.3 * std::cos(2 * aurorawall::physics::kPi * 5 * i / nx);
    MacVelocity vel{PeriodicField(nx, ny, h, h), PeriodicField(nx, ny, h, h)};
    for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i) {
            vel.u(i, j) = (psi(i, j) - psi(i - 1, j)) / h + std::sin(2 * aurorawall::physics::kPi * j / ny);
            vel.v(i, j) = (psi(i, j) - psi(i, j - 1)) / h;
        }
    PeriodicField phi(nx, ny, h, h);
    ASSERT_TRUE(project(vel, phi, {30, 1e-12, 2, 2}).converged);
    double error = 0.0;
    for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i)
            error = std::max({error, std::abs(vel.u(i, j) - std::sin(2 * aurorawall::physics::kPi * j / ny)), std::abs(vel.v(i, j))});
    EXPECT_LT(error, 1e-9);
}

TEST(Projection, FftLeavesDivergenceAtRoundingLevel)
{
    // The default strip's grid and one with hx ≠ hy.
    for (const auto& [nx, ny, hx, hy] : {std::tuple{512, 128, 0.25, 0.25}, std::tuple{256, 64, 0.5, 0.375}}) {
        MacVelocity vel = roughVelocity(nx, ny, hx);
        for (PeriodicField* f : {&vel.u, &vel.v})
            f->hy = hy;
        const double before = divergenceRms(vel) / gradientRms(vel);
        PeriodicField phi(nx, ny, hx, hy);
        FftPoisson solver(nx, ny, hx, hy);
        project(vel, phi, solver);
        const double after = divergenceRms(vel) / gradientRms(vel);
        std::printf("  %dx%d: rms div / rms |grad u|: %.3e before, %.3e after the FFT projection\n", nx, ny, before, after);
        EXPECT_LE(after, 1e-12); // rounding: a million times below the multigrid's default tolerance
    }
}

TEST(Projection, FftAgreesWithMultigridSolvedToAResidualOf1e12)
{
    MacVelocity fft = roughVelocity(512, 128, 0.25);
    MacVelocity multigrid = fft;
    PeriodicField phi(512, 128, 0.25, 0.25);
    FftPoisson solver(512, 128, 0.25, 0.25);
    project(fft, phi, solver);
    PeriodicField phiMultigrid(512, 128, 0.25, 0.25);
    ASSERT_TRUE(project(multigrid, phiMultigrid, {60, 1e-12, 2, 2}).converged);
    double difference = 0.0, scale = 0.0;
    for (std::size_t k = 0; k < fft.u.values.size(); ++k) {
        difference = std::max({difference, std::abs(fft.u.values[k] - multigrid.u.values[k]),
                               std::abs(fft.v.values[k] - multigrid.v.values[k])});
        scale = std::max({scale, std::abs(multigrid.u.values[k]), std::abs(multigrid.v.values[k])});
    }
    std::printf("  max |u_fft - u_multigrid| / max |u| = %.2e\n", difference / scale);
    EXPECT_LT(difference / scale, 1e-11);
}

TEST(Projection, FftKeepsADivergenceFreeFieldAndRemovesAGradient)
{
    // u = ∂ψ/∂y, v = −∂ψ/∂x from a stream function ψ at the cell corners (face differences) is
    // discretely divergence-free and kept; a face gradient of a cell-centred φ is removed.
    const int nx = 128, ny = 64;
    const double hx = 0.25, hy = 0.3;
    PeriodicField psi(nx, ny, hx, hy);
    PeriodicField grad(nx, ny, hx, hy);
    HashNoise noise{21u};
    for (double& q : psi.values)
        q = noise.next();
    for (double& q : grad.values)
        q = noise.next();
    MacVelocity solenoidal{PeriodicField(nx, ny, hx, hy), PeriodicField(nx, ny, hx, hy)};
    for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i) {
            solenoidal.u(i, j) = (psi(i, j + 1) - psi(i, j)) / hy;
            solenoidal.v(i, j) = -(psi(i + 1, j) - psi(i, j)) / hx;
        }
    MacVelocity vel = solenoidal;
    PeriodicField phi(nx, ny, hx, hy);
    FftPoisson solver(nx, ny, hx, hy);
    project(vel, phi, solver);
    EXPECT_LT(maxAbsDifference(vel, solenoidal), 1e-13);
    for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i) {
            vel.u(i, j) = solenoidal.u(i, j) + (grad(i, j) - grad(i - 1, j)) / hx;
            vel.v(i, j) = solenoidal.v(i, j) + (grad(i, j) - grad(i, j - 1)) / hy;
        }
    project(vel, phi, solver);
    EXPECT_LT(maxAbsDifference(vel, solenoidal), 1e-12);
}

TEST(Advection, UniformFlowShiftsByWholeCellsExactly)
{
    // u = 1 km/s, v = −0.5 km/s, h = 0.25 km, dt = 0.5 s: the scalar moves by (+2, −1) cells.
    const int nx = 64, ny = 32;
    MacVelocity vel{PeriodicField(nx, ny, 0.25, 0.25), PeriodicField(nx, ny, 0.25, 0.25)};
    std::fill(vel.u.values.begin(), vel.u.values.end(), 1.0);
    std::fill(vel.v.values.begin(), vel.v.values.end(), -0.5);
    PeriodicField q(nx, ny, 0.25, 0.25);
    HashNoise noise{3u};
    for (double& value : q.values)
        value = noise.next();
    PeriodicField moved = q;
    advectScalar(moved, vel, 0.5);
    for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i)
            ASSERT_EQ(moved(i + 2, j - 1), q(i, j)) << i << "," << j;
    advectVelocity(vel, 0.5);
    EXPECT_EQ(vel.u.values, std::vector<double>(nx * ny, 1.0));
}

TEST(Advection, IsMonotoneInARotatingFlow)
{
    // Cellular flow ψ = sin(kx) sin(ky) (divergence-free), rough scalar in [0, 1).
    const int n = 64;
    const double h = 1.0, k = 2 * aurorawall::physics::kPi / (n * h);
    MacVelocity vel{PeriodicField(n, n, h, h), PeriodicField(n, n, h, h)};
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            vel.u(i, j) = std::sin(k * i * h) * std::cos(k * (j + 0.5) * h);
            vel.v(i, j) = -std::cos(k * (i + 0.5) * h) * std::sin(k * j * h);
        }
    PeriodicField q(n, n, h, h);
    HashNoise noise{11u};
    for (double& value : q.values)
        value = noise.next() + 0.5;
    const auto [lo, hi] = std::minmax_element(q.values.begin(), q.values.end());
    const double min0 = *lo, max0 = *hi;
    for (int step = 0; step < 50; ++step) {
        advectScalar(q, vel, 3.0);
        const auto [l, u] = std::minmax_element(q.values.begin(), q.values.end());
        ASSERT_GE(*l, min0);
        ASSERT_LE(*u, max0);
    }
}

} // namespace
} // namespace aurorawall::components::fluid_detail::simulation
