// The particle-in-cell plasma's core in double: the shared kernels (shaders/components/plasma, here
// compiled as C++ in double), the Poisson solvers, determinism, the plasma dispersion function, and
// each case of `aurorawall plasma verify` against theory.
#include "physics/constants.h"
#include "common/glsl.h"
#include "components/plasma/simulation/discrete_laplacian.h"
#include "components/plasma/simulation/dispersion.h"
#include "components/plasma/simulation/electrostatic_pic.h"
#include "components/plasma/simulation/fft_poisson_solver.h"
#include "components/plasma/simulation/jacobi_poisson.h"
#include "components/plasma/simulation/particle_loading.h"
#include "components/plasma/simulation/particle_mesh.h"
#include "components/plasma/simulation/plasma_parameters.h"
#include "components/plasma/simulation/verify_cases.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <map>
#include <random>
#include <sstream>
#include <string>

// The shared kernels in double (a named namespace: not every function is used).
namespace aurorawall::plasma_test::f64 {
AURORAWALL_GLSL_PRECISION(double)
#include "components/plasma/cloud_in_cell.glsl"
#include "components/plasma/electric_field.glsl"
#include "components/plasma/boris_push.glsl"
} // namespace aurorawall::plasma_test::f64

using namespace aurorawall;
using namespace aurorawall::components::plasma::simulation;
namespace f64 = aurorawall::plasma_test::f64;

namespace {


// The measured row of a verify case (the one with an expected value and this parameter).
VerifyRow row(const std::vector<VerifyRow>& rows, const std::string& parameter)
{
    for (const VerifyRow& r : rows)
        if (r.parameter == parameter && r.expected)
            return r;
    ADD_FAILURE() << "no row " << parameter;
    return {};
}

} // namespace

// The 2^dimension CIC weights are the products of the linear weights and sum to 1.
TEST(PlasmaKernels, CloudInCellWeightsSumToOneAndAreLinear)
{
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> u(-5.0, 5.0);
    for (int dimension = 1; dimension <= 3; ++dimension)
        for (int trial = 0; trial < 100; ++trial) {
            const glm::dvec3 g(u(rng), u(rng), u(rng));
            const glm::dvec3 f = f64::cicCellFraction(g);
            double sum = 0.0;
            for (int corner = 0; corner < (1 << dimension); ++corner) {
                double product = 1.0;
                for (int d = 0; d < dimension; ++d)
                    product *= (corner >> d) & 1 ? f[d] : 1.0 - f[d];
                EXPECT_DOUBLE_EQ(f64::cicCornerWeight(f, corner, dimension), product);
                sum += f64::cicCornerWeight(f, corner, dimension);
            }
            EXPECT_NEAR(sum, 1.0, 1e-15);
            // The weights reproduce the position: Σ w·node = g along each axis.
            for (int d = 0; d < dimension; ++d) {
                double centroid = 0.0;
                for (int corner = 0; corner < (1 << dimension); ++corner)
                    centroid += f64::cicCornerWeight(f, corner, dimension) * (std::floor(g[d]) + ((corner >> d) & 1));
                EXPECT_NEAR(centroid, g[d], 1e-14);
            }
        }
}

// The central difference is exact for a quadratic potential: −(φ(x+h) − φ(x−h))/2h = −φ'(x).
TEST(PlasmaKernels, CentralDifferenceIsExactForAQuadratic)
{
    const auto phi = [](double x) { return 3.0 * x * x - 2.0 * x + 1.0; };
    const double x = 0.7, h = 0.01;
    EXPECT_NEAR(f64::centralDifferenceField(phi(x - h), phi(x + h), h), -(6.0 * x - 2.0), 1e-12);
}

// One Boris step in a pure B is the rotation by 2·atan(ω_cΔt/2) about B (Rodrigues' formula), for
// small and very large ω_cΔt.
TEST(PlasmaKernels, BorisStepIsTheExactRotation)
{
    const glm::dvec3 b = glm::normalize(glm::dvec3(0.3, -0.4, 0.8)) * 5e-5;
    const glm::dvec3 v(2e5, 1e5, -3e5);
    const double qm = -kElementaryCharge / kElectronMass;
    for (const double wcDt : {1e-3, 0.5, 2.0, 100.0}) {
        const double dt = wcDt / cyclotronFrequency(glm::length(b));
        // dv/dt = (q/m) v×B = Ω×v, Ω = −(q/m)B: an electron turns right-handedly about B.
        const glm::dvec3 axis = glm::normalize(b);
        const double angle = 2.0 * std::atan(0.5 * wcDt);
        const glm::dvec3 expected = v * std::cos(angle) + glm::cross(axis, v) * std::sin(angle) +
                                    axis * glm::dot(axis, v) * (1.0 - std::cos(angle));
        const glm::dvec3 got = f64::borisVelocity(v, glm::dvec3(0.0), b, qm, dt);
        EXPECT_LT(glm::length(got - expected), 1e-14 * glm::length(v)) << "omega_c dt = " << wcDt;
    }
}

// No self-force: a lone particle's own field, deposited, solved and gathered with the same weights,
// vanishes at the particle (1D and 2D, anywhere in its cell).
TEST(PlasmaMesh, NoSelfForce)
{
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (int dimension = 1; dimension <= 2; ++dimension) {
        const PeriodicGrid grid(dimension, {16, 16, 1}, {0.1, 0.1, 1.0});
        const FftPoissonSolver solver(grid);
        for (int trial = 0; trial < 20; ++trial) {
            Particles one;
            one.position = {glm::dvec3(u(rng) * 1.6, u(rng) * 1.6, 0.5)};
            one.velocity = {glm::dvec3(0.0)};
            const std::vector<glm::dvec3> nodes =
                nodeElectricField(grid, solver.solve(depositChargeDensity(grid, one)));
            double scale = 0.0;
            for (const glm::dvec3& e : nodes) scale = std::max(scale, glm::length(e));
            const glm::dvec3 self = gatherField(grid, nodes, one.position)[0];
            EXPECT_LT(glm::length(self), 1e-12 * scale) << "dimension " << dimension;
        }
    }
}

// The FFT solve gives the closed-form potential of one Fourier mode, ρ = cos(2πmx/L) →
// φ = ρ/(ε₀ K²), K² = (4/Δx²) sin²(πm/n), and leaves a residual at rounding on random charge in 3D.
TEST(PlasmaPoisson, FftSolvesTheDiscreteEquation)
{
    const PeriodicGrid line(1, {32, 1, 1}, {0.05, 1.0, 1.0});
    std::vector<double> rho(32);
    const int mode = 3;
    for (int j = 0; j < 32; ++j) rho[j] = std::cos(2.0 * aurorawall::physics::kPi * mode * j / 32);
    const std::vector<double> phi = FftPoissonSolver(line).solve(rho);
    const double s = std::sin(aurorawall::physics::kPi * mode / 32);
    const double k2 = 4.0 * s * s / (0.05 * 0.05);
    for (int j = 0; j < 32; ++j)
        EXPECT_NEAR(phi[j], rho[j] / (kVacuumPermittivity * k2), 1e-12 / (kVacuumPermittivity * k2));

    const PeriodicGrid box(3, {16, 8, 12}, {0.1, 0.2, 0.15});
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    std::vector<double> random(box.nodeCount());
    for (double& r : random) r = u(rng);
    const std::vector<double> potential = FftPoissonSolver(box).solve(random);
    EXPECT_LT(poissonResidual(box, random, potential), 1e-12);
    double mean = 0.0;
    for (double p : potential) mean += p;
    EXPECT_NEAR(mean / double(potential.size()), 0.0, 1e-12 * std::abs(potential[0]));
}

// Plain Jacobi never converges on an even periodic grid: the checkerboard (−1)^(i+j+k) is an
// eigenvector of its iteration with eigenvalue −1, flipped every sweep and never damped.
TEST(PlasmaPoisson, JacobiNeverDampsTheCheckerboard)
{
    const PeriodicGrid grid(3, {8, 8, 8}, {0.1, 0.2, 0.3});
    const std::vector<double> noCharge(grid.nodeCount(), 0.0);
    std::vector<double> phi(grid.nodeCount());
    for (int k = 0; k < 8; ++k)
        for (int j = 0; j < 8; ++j)
            for (int i = 0; i < 8; ++i) phi[grid.index(i, j, k)] = (i + j + k) % 2 == 0 ? 1.0 : -1.0;
    const std::vector<double> start = phi;
    jacobiSweeps(grid, noCharge, phi, 1001);
    for (std::size_t n = 0; n < phi.size(); ++n)
        ASSERT_NEAR(phi[n], -start[n], 1e-12);

    // So from a random start, once every other mode has decayed (the slowest here has |μ| = 0.976), the
    // residual stalls where the FFT's is at rounding.
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    std::vector<double> rho(grid.nodeCount()), guess(grid.nodeCount());
    for (double& r : rho) r = u(rng) * 1e-9;
    for (double& g : guess) g = u(rng);
    jacobiSweeps(grid, rho, guess, 2000);
    const double stalled = poissonResidual(grid, rho, guess);
    jacobiSweeps(grid, rho, guess, 1);
    EXPECT_GT(stalled, 0.1);
    EXPECT_NEAR(poissonResidual(grid, rho, guess), stalled, 1e-9 * stalled);
    EXPECT_LT(poissonResidual(grid, rho, FftPoissonSolver(grid).solve(rho)), 1e-12);
}

// Deposition in a fixed order: two runs from the same seed give the same bits.
TEST(PlasmaSimulation, TwoRunsGiveIdenticalBits)
{
    const PeriodicGrid grid(2, {16, 16, 1}, {0.01, 0.01, 1.0});
    const auto run = [&grid] {
        ElectrostaticPic pic(grid, randomStart(grid, 2048, 1e12, 4.19e5, 42), glm::dvec3(0.0, 0.0, 5e-5), 2e-9);
        for (int n = 0; n < 100; ++n) pic.step();
        return pic.electrons();
    };
    const Particles a = run(), b = run();
    ASSERT_EQ(a.position.size(), b.position.size());
    EXPECT_EQ(std::memcmp(a.position.data(), b.position.data(), a.position.size() * sizeof(glm::dvec3)), 0);
    EXPECT_EQ(std::memcmp(a.velocity.data(), b.velocity.data(), a.velocity.size() * sizeof(glm::dvec3)), 0);
}

// No NaN or Inf over 1e5 steps of a small magnetised thermal plasma near the leapfrog's limit.
TEST(PlasmaSimulation, StaysFiniteOverAHundredThousandSteps)
{
    const double density = 1e12, thermalSpeed = 4.19e5;
    const PeriodicGrid grid(1, {16, 1, 1}, {debyeLength(thermalSpeed, density), 1.0, 1.0});
    const double dt = 1.5 / plasmaFrequency(density);
    ElectrostaticPic pic(grid, randomStart(grid, 64, density, thermalSpeed, 9), glm::dvec3(0.0, 3e-4, 0.0), dt);
    StepEnergies last;
    for (long n = 0; n < 100000; ++n) last = pic.step();
    EXPECT_TRUE(std::isfinite(last.total()));
    for (std::size_t p = 0; p < 64; ++p)
        for (int d = 0; d < 3; ++d) {
            ASSERT_TRUE(std::isfinite(pic.electrons().position[p][d]));
            ASSERT_TRUE(std::isfinite(pic.electrons().velocity[p][d]));
        }
}

// Z against Dawson's integral at real arguments (Z(x) = i√π exp(−x²) − 2F(x); F from Abramowitz &
// Stegun table 7.5), the series against the continued fraction across |ζ| = 4 and below the real
// axis, and Z' = −2(1 + ζZ) by central differences in the lower half plane.
TEST(PlasmaDispersion, PlasmaDispersionFunction)
{
    const double sqrtPi = std::sqrt(aurorawall::physics::kPi);
    EXPECT_NEAR(std::abs(plasmaDispersionZ(0.0) - std::complex<double>(0.0, sqrtPi)), 0.0, 1e-15);
    const double dawson[][2] = {{1.0, 0.5380795069127684}, {2.0, 0.3013403889237920}, {3.0, 0.1782710306105583}};
    for (const auto& [x, f] : dawson) {
        const std::complex<double> z = plasmaDispersionZ(x);
        EXPECT_NEAR(z.real(), -2.0 * f, 1e-13) << x;
        EXPECT_NEAR(z.imag(), sqrtPi * std::exp(-x * x), 1e-13) << x;
    }
    // The continued fraction (|ζ| ≥ 4) against the series just beyond its default range (where the
    // series' cancellation still leaves ~1e-8).
    for (const std::complex<double> zeta : {std::complex<double>(4.2, 0.3), std::complex<double>(3.0, -3.0),
                                            std::complex<double>(-4.1, -0.5), std::complex<double>(0.5, 4.05)}) {
        std::complex<double> term = zeta, series = zeta;
        for (int n = 1; n < 400; ++n) {
            term *= -2.0 * zeta * zeta / double(2 * n + 1);
            series += term;
        }
        const std::complex<double> bySeries = std::complex<double>(0.0, sqrtPi) * std::exp(-zeta * zeta) - 2.0 * series;
        EXPECT_LT(std::abs(plasmaDispersionZ(zeta) - bySeries), 1e-7 * std::abs(bySeries)) << zeta;
    }
    for (const std::complex<double> zeta : {std::complex<double>(2.0, -0.2), std::complex<double>(5.0, -1.0)}) {
        const double h = 1e-5;
        const std::complex<double> derivative = (plasmaDispersionZ(zeta + h) - plasmaDispersionZ(zeta - h)) / (2.0 * h);
        const std::complex<double> expected = -2.0 * (1.0 + zeta * plasmaDispersionZ(zeta));
        EXPECT_LT(std::abs(derivative - expected), 1e-8 * std::abs(expected)) << zeta;
    }
}

// The Landau root at kλ_D = 0.5: ω = (1.415662 − 0.153359 i) ω_p (Canosa 1973; McKinstrie et al. 1999).
TEST(PlasmaDispersion, LandauRootMatchesThePublishedValue)
{
    const std::complex<double> root = landauRoot(0.5);
    EXPECT_NEAR(root.real(), 1.415662, 1e-6);
    EXPECT_NEAR(root.imag(), -0.153359, 1e-6);
}

// The cold two-stream rate peaks at k v₀ = √(3/8) ω_p with γ = ω_p/(2√2); stable from k v₀ = ω_p on.
TEST(PlasmaDispersion, TwoStreamGrowthRate)
{
    const double peak = std::sqrt(3.0 / 8.0);
    EXPECT_NEAR(twoStreamGrowthRate(peak), 1.0 / (2.0 * std::sqrt(2.0)), 1e-15);
    EXPECT_LT(twoStreamGrowthRate(0.99 * peak), twoStreamGrowthRate(peak));
    EXPECT_LT(twoStreamGrowthRate(1.01 * peak), twoStreamGrowthRate(peak));
    EXPECT_EQ(twoStreamGrowthRate(1.0), 0.0);
}

// Langmuir: the leapfrog relation to 2e-5. The remaining 5e-6 is the grid's own dispersion,
// −(kΔx)²/8 = −4.7e-6 at kΔx = 2π/1024; the leapfrog's shift it resolves is 1.7e-3 and 4.7e-2.
TEST(PlasmaVerify, LangmuirFollowsTheLeapfrogRelation)
{
    EXPECT_NEAR(leapfrogPlasmaFrequency(0.2), 1.001674, 1e-6);
    EXPECT_NEAR(leapfrogPlasmaFrequency(1.0), 1.047198, 1e-6);
    for (const double wpDt : {0.2, 1.0}) {
        const VerifyRow r = row(verifyLangmuir(wpDt), "omega_over_wp");
        EXPECT_LT(r.relativeError(), 2e-5) << "omega_p dt = " << wpDt << ": " << r.measured;
    }
}

// Boris: the rotation per step to rounding; |v| kept to rounding, about 1e-16 per step (measured
// 2e-14 after 1e3 steps, 1.5e-11 after 1e5 at ω_cΔt = 100); the orbit bounded over 1e5 steps at ω_cΔt = 100.
TEST(PlasmaVerify, BorisRotatesExactlyAndKeepsTheSpeed)
{
    for (const double wcDt : {0.1, 1.0, 100.0}) {
        const long steps = wcDt == 100.0 ? 100000 : 1000;
        const std::vector<VerifyRow> rows = verifyBoris(wcDt, steps);
        EXPECT_LT(row(rows, "rotation_per_step_rad").relativeError(), 1e-12) << wcDt;
        EXPECT_LT(row(rows, "max_relative_speed_change").measured, 1e-15 * double(steps)) << wcDt;
    }
    // The discrete orbit is a polygon inscribed in a circle of radius |v⊥|Δt/(2 sin(θ/2)).
    const double b = 5e-5, dt = 100.0 / cyclotronFrequency(b), theta = 2.0 * std::atan(50.0);
    const glm::dvec3 start(50.0), box(100.0); // m; the orbit's radius is 1.7 m
    glm::dvec3 x = start, v(3e5, 0.0, 0.0);
    const double radius = 3e5 * dt / (2.0 * std::sin(0.5 * theta));
    double farthest = 0.0;
    for (long n = 0; n < 100000; ++n) {
        v = f64::borisVelocity(v, glm::dvec3(0.0), glm::dvec3(0.0, 0.0, b), -kElementaryCharge / kElectronMass, dt);
        x = f64::leapfrogPosition(x, v, dt, box);
        farthest = std::max(farthest, glm::length(x - start));
    }
    EXPECT_LE(farthest, 2.0 * radius * (1.0 + 1e-9));
    EXPECT_GT(farthest, 1.9 * radius);
}

// E×B: the centre of the velocity circle is E×B/B² to rounding for any Δt.
TEST(PlasmaVerify, ExBDriftIsExact)
{
    for (const double wcDt : {0.1, 1.0, 100.0}) {
        const std::vector<VerifyRow> rows = verifyExB(wcDt);
        EXPECT_LT(row(rows, "drift_along_ExB_over_E_over_B").relativeError(), 1e-10) << wcDt;
        EXPECT_LT(std::abs(row(rows, "drift_along_E_over_E_over_B").measured), 1e-10) << wcDt;
    }
}

// Two-stream: the growth rate to 0.5% at ω_pΔt = 0.2 (measured 0.003%; fitted from 6 to 16
// e-foldings of a 1e-9 seed it measured 0.14%); an unseeded, quiet start: no noise.
TEST(PlasmaVerify, TwoStreamGrowsAtTheColdRate)
{
    EXPECT_LT(row(verifyTwoStream(0.2), "growth_rate_over_wp").relativeError(), 5e-3);
}

// Energy: the total energy of a thermal plasma with Δx = λ_D drifts by 0.34% over 200 plasma periods
// at ω_pΔt = 0.2 (the grid's slow heating); bounded at 1%. Deterministic (seeded), so the bound is
// a regression bound on the scheme, not on noise.
TEST(PlasmaVerify, TotalEnergyDriftsLittle)
{
    EXPECT_LT(std::abs(row(verifyEnergy(0.2), "relative_energy_drift").measured), 1e-2);
}

// Landau: frequency to 0.5% and damping rate to 2% (measured 0.09% and 0.4%; over fit windows between
// 4–16 and 6–26 /ω_p the measurement moves by 0.3% and 1%: the particles' noise).
TEST(PlasmaVerify, LandauDampingMatchesTheKineticRoot)
{
    const std::vector<VerifyRow> rows = verifyLandau(0.2);
    EXPECT_LT(row(rows, "frequency_over_wp").relativeError(), 5e-3);
    EXPECT_LT(row(rows, "damping_rate_over_wp").relativeError(), 2e-2);
}

// Landau at another wave number, kλ_D = 0.4 (the weakly damped side: γ = −0.0661 ω_p, a 0.87% wave
// over 45 /ω_p), with a quarter of the command's particles: measured 0.06% off in frequency and 1.0%
// in damping rate; held to 0.5% and 3% (the kλ_D = 0.5 bounds, the damping's widened for the
// doubled noise of a quarter of the particles).
TEST(PlasmaVerify, LandauDampingAtAnotherWaveNumber)
{
    const std::vector<VerifyRow> rows = verifyLandau(0.2, 0.4, 1 << 18);
    std::printf("landau at k lambda_D = 0.4: frequency %.4g, damping %.4g (relative errors)\n",
                row(rows, "frequency_over_wp").relativeError(), row(rows, "damping_rate_over_wp").relativeError());
    EXPECT_TRUE(std::any_of(rows.begin(), rows.end(),
                            [](const VerifyRow& r) { return r.parameter == "k_debye" && r.measured == 0.4; }));
    EXPECT_LT(row(rows, "frequency_over_wp").relativeError(), 5e-3);
    EXPECT_LT(row(rows, "damping_rate_over_wp").relativeError(), 3e-2);
    EXPECT_THROW(verifyLandau(0.2, kLandauMinKDebye - 0.01), std::domain_error);
    EXPECT_THROW(verifyLandau(0.2, kLandauMaxKDebye + 0.01), std::domain_error);
}

// Outside the leapfrog's stability, and where the step counts (∝ 1/ω_pΔt) or the rounding of the
// gyration run away, the cases refuse to run: at ω_pΔt = 1e-300 the counts overflowed and langmuir
// measured NaN, exb did at ω_cΔt = 1e-300 and 1e300, and heating at Δx/λ_D = 1e300.
TEST(PlasmaVerify, RefusesAnUnstableOrUnresolvedTimeStep)
{
    EXPECT_THROW(verifyLangmuir(2.0), std::domain_error);
    EXPECT_THROW(verifyLangmuir(1e-300), std::domain_error);
    EXPECT_THROW(verifyTwoStream(-0.1), std::domain_error);
    EXPECT_THROW(verifyHeating(std::nextafter(kMinVerifyWpDt, 0.0), 1.0), std::domain_error);
    EXPECT_THROW(verifyBoris(0.0), std::domain_error);
    EXPECT_THROW(verifyExB(1e-300), std::domain_error);
    EXPECT_THROW(verifyExB(std::nextafter(kMaxVerifyWcDt, 2e6)), std::domain_error);
    EXPECT_THROW(verifyHeating(0.2, 1e300), std::domain_error);
    EXPECT_THROW(verifyHeating(0.2, std::nextafter(kMinHeatingDxDebye, 0.0)), std::domain_error);
}

// At a coarse ω_pΔt (1.5 to 2, under 5 samples per period) the largest |field| between two zero
// crossings can be the first sample past one, smaller than the sample before it: the parabola through
// them bent up and its peak's logarithm was NaN. The damping rate is then poor, but finite.
TEST(PlasmaVerify, LandauAtACoarseTimeStepMeasuresAFiniteRate)
{
    for (const double wpDt : {1.5, 1.9, std::nextafter(2.0, 0.0)}) {
        const std::vector<VerifyRow> rows = verifyLandau(wpDt, 0.5, 1 << 16);
        EXPECT_TRUE(std::isfinite(row(rows, "damping_rate_over_wp").measured)) << wpDt;
        EXPECT_TRUE(std::isfinite(row(rows, "frequency_over_wp").measured)) << wpDt;
    }
}

namespace {

// A diagonal Langmuir wave of |k|Δx = kDx, run by verify(ω_pΔt) at ω_pΔt = 0.2 and 1: its frequency is
// the leapfrog relation's times the grid's dispersion 1 − (|k|Δx)²/8, to 15% of that dispersion.
template <class Verify>
void expectTheGridDispersion(const char* name, double kDx, Verify verify)
{
    const double gridDispersion = kDx * kDx / 8.0;
    for (const double wpDt : {0.2, 1.0}) {
        const VerifyRow r = row(verify(wpDt), "omega_over_wp");
        const double signedError = (r.measured - *r.expected) / *r.expected;
        std::printf("%s, omega_p dt = %g: relative error %.5g, grid dispersion %.5g\n", name, wpDt, signedError,
                    -gridDispersion);
        EXPECT_NEAR(signedError, -gridDispersion, 0.15 * gridDispersion) << name << ", omega_p dt = " << wpDt;
    }
}

} // namespace

// Langmuir in 2D, the wave along the diagonal of a 64² grid (the command uses 256²): its frequency is
// the leapfrog relation's times the grid's dispersion 1 − (|k|Δx)²/8, |k|Δx = √2·2π/64 (2.41e-3).
// Measured: the relative error is that dispersion to 0.25% of it at ω_pΔt = 0.2 and to 10% at 1 (the
// time step's own share); on 32² and 128² grids alike. Held to 15%.
TEST(PlasmaVerify, Langmuir2DFollowsTheLeapfrogRelationAndTheGridDispersion)
{
    constexpr int kCells = 64;
    expectTheGridDispersion("langmuir-2d, 64^2", std::sqrt(2.0) * 2.0 * aurorawall::physics::kPi / kCells,
                            [](double wpDt) { return verifyLangmuir2D(wpDt, kCells); });
}

namespace {

// The heating case's rate d(kT)/dt/(kT ω_p).
double heatingRate(double dxOverDebye, std::uint64_t seed)
{
    for (const VerifyRow& r : verifyHeating(0.2, dxOverDebye, seed))
        if (r.parameter == "heating_rate_over_wp")
            return r.measured;
    ADD_FAILURE() << "no heating rate";
    return std::nan("");
}

} // namespace

// Grid heating: negligible for Δx/λ_D = 0.5, growing with Δx/λ_D. Over seeds 1–6 the rate at
// Δx/λ_D = 0.5 scattered between −1.1e-6 and 5.5e-6 (the particles' noise: no heating resolved), at
// 2 between 7.0e-5 and 1.5e-4, at 8 between 2.4e-3 and 3.9e-3. Bounds: |rate| < 2e-5 at 0.5 (about
// four times the largest noise seen), and at 8 at least ten times the rate at 0.5 and above the rate at 2.
TEST(PlasmaVerify, GridHeatingGrowsWithTheSpacingInDebyeLengths)
{
    for (const std::uint64_t seed : {1u, 2u}) {
        const double resolved = heatingRate(0.5, seed), coarse = heatingRate(2.0, seed),
                     coarsest = heatingRate(8.0, seed);
        ASSERT_TRUE(std::isfinite(resolved) && std::isfinite(coarse) && std::isfinite(coarsest)) << seed;
        EXPECT_LT(std::abs(resolved), 2e-5) << seed;
        EXPECT_GT(coarse, std::abs(resolved)) << seed;
        EXPECT_GT(coarsest, coarse) << seed;
        EXPECT_GE(coarsest, 10.0 * std::abs(resolved)) << seed;
    }
    EXPECT_THROW(verifyHeating(0.2, 0.0), std::domain_error);
    EXPECT_THROW(verifyHeating(2.0, 1.0), std::domain_error);
}

// In a wide box the periodic rate is Levy's ½√(e^{−4ka} − (1 − 2ka)²) for a strip in free space
// (the images and the background's share fall as e^{−kL} and 2a/L): its maximum 0.2012 near ka = 0.4,
// and no growth beyond the root of e^{−2ka} = 2ka − 1 (ka = 0.6392).
TEST(PlasmaDispersion, DiocotronRateTendsToLevysStrip)
{
    for (double ka : {0.1, 0.25, 0.4, 0.6}) {
        const double levy = 0.5 * std::sqrt(std::exp(-4.0 * ka) - (1.0 - 2.0 * ka) * (1.0 - 2.0 * ka));
        EXPECT_NEAR(diocotronGrowthRate(ka, 2e4), levy, 1e-3 * levy) << ka;
    }
    EXPECT_NEAR(diocotronGrowthRate(0.4, 2e4), 0.2012, 1e-4);
    EXPECT_GT(diocotronGrowthRate(0.63, 2e4), 0.0);
    EXPECT_EQ(diocotronGrowthRate(0.65, 2e4), 0.0);
    // A narrower box slows the growth: the background's shear and the images oppose it.
    EXPECT_LT(diocotronGrowthRate(0.4, 2.0 * aurorawall::physics::kPi * 0.5), diocotronGrowthRate(0.4, 2e4));
    EXPECT_THROW(diocotronGrowthRate(0.4, 0.8), std::domain_error);
}

// The strip's mode grows at the guiding-centre rate: measured 0.89% slow at ω_cΔt = 5 and
// ω_p/ω_c = 0.1 (with a 1e-8 seed fitted to 14 e-foldings: 0.04% at ω_cΔt = 1; 1.8% at
// ω_p/ω_c = 0.2, the finite-inertia correction), the lattice start has no noise, so 2% bounds it.
TEST(PlasmaVerify, DiocotronGrowsAtTheGuidingCentreRate)
{
    const VerifyRow r = row(verifyDiocotron(5.0, 0.1), "growth_rate_over_wd");
    EXPECT_LT(r.relativeError(), 2e-2) << r.measured << " vs " << *r.expected;
    EXPECT_THROW(verifyDiocotron(5.0, 1.0), std::domain_error);
    EXPECT_THROW(verifyDiocotron(25.0, 0.1), std::domain_error);
}

// The wave along the body diagonal of a 16³ grid (the command uses 32³): the leapfrog relation times
// the grid's dispersion 1 − (|k|Δx)²/8, |k|Δx = √3·2π/16 (5.78e-2), as in 2D. Measured: the relative
// error is that dispersion to 1.9% of it at ω_pΔt = 0.2 and to 6.8% at 1 (on 32³: 0.24% and 9.4%).
// Held to 15%, as in 2D.
TEST(PlasmaVerify, Langmuir3DFollowsTheLeapfrogRelationAndTheGridDispersion)
{
    constexpr int kCells = 16;
    expectTheGridDispersion("langmuir-3d, 16^3", std::sqrt(3.0) * 2.0 * aurorawall::physics::kPi / kCells,
                            [](double wpDt) { return verifyLangmuir3D(wpDt, kCells); });
    EXPECT_THROW(verifyLangmuir3D(2.0), std::domain_error);
}

namespace {

// A history written by writeHistoryCsv, read back: the "# name = value" lines and the table by column.
struct WrittenHistory {
    std::map<std::string, double> fit;
    std::map<std::string, std::vector<double>> columns;
};

WrittenHistory writtenHistory(const VerifyHistory& history)
{
    std::ostringstream csv;
    writeHistoryCsv(csv, history);
    std::istringstream in(csv.str());
    WrittenHistory written;
    std::vector<std::string> names;
    std::string line;
    while (std::getline(in, line)) {
        if (line.rfind("# ", 0) == 0) {
            const std::size_t equals = line.find(" = ");
            written.fit[line.substr(2, equals - 2)] = std::stod(line.substr(equals + 3));
            continue;
        }
        std::istringstream cells(line);
        std::string cell;
        for (std::size_t c = 0; std::getline(cells, cell, ','); ++c) {
            if (names.size() < history.columns.size())
                names.push_back(cell);
            else
                written.columns[names[c]].push_back(std::stod(cell));
        }
    }
    return written;
}

} // namespace

// The langmuir history is the mode at every step of the 20 plasma periods, from t = 0 at ω_pΔt apart,
// and the frequency refitted from the written samples (9 significant digits) is the printed one: the
// samples' rounding (5e-10) moves cos(ωΔt) by about that, ωΔt by 5e-9 at ω_pΔt = 0.2, far below 1e-7.
TEST(PlasmaVerify, LangmuirHistoryHoldsTheSamplesTheFrequencyCameFrom)
{
    constexpr double kWpDt = 0.2;
    VerifyHistory history;
    const VerifyRow r = row(verifyLangmuir(kWpDt, cpuDevice(), &history), "omega_over_wp");
    const WrittenHistory written = writtenHistory(history);
    const std::vector<double>& t = written.columns.at("t_wp");
    const std::vector<double>& s = written.columns.at("field_mode");
    ASSERT_EQ(t.size(), std::size_t(std::ceil(20 * 2.0 * aurorawall::physics::kPi / kWpDt)) + 1);
    ASSERT_EQ(s.size(), t.size());
    for (std::size_t n = 0; n < t.size(); ++n)
        EXPECT_NEAR(t[n], double(n) * kWpDt, 1e-9 * t.back());
    // An independent least squares for cos(ωΔt): s_{n+1} + s_{n−1} = 2 cos(ωΔt) s_n.
    double numerator = 0.0, denominator = 0.0;
    for (std::size_t n = 1; n + 1 < s.size(); ++n) {
        numerator += s[n] * (s[n + 1] + s[n - 1]);
        denominator += 2.0 * s[n] * s[n];
    }
    const double refitted = std::acos(numerator / denominator) / kWpDt;
    EXPECT_NEAR(refitted, r.measured, 1e-7 * r.measured);
    EXPECT_NEAR(written.fit.at("fitted_omega"), r.measured, 1e-8 * r.measured);
    EXPECT_NEAR(written.fit.at("expected_omega"), *r.expected, 1e-8 * *r.expected);
}

// The two-stream history holds every step from t = 0, the fit's window (from 6 e-foldings of the
// expected rate) marked; the slope of ln|E_1| refitted over the marked written samples is the printed
// growth rate (to 1e-7: the samples carry 9 digits, the window 3 e-foldings), and the window's samples
// grow by about e³ from the first to the last.
TEST(PlasmaVerify, TwoStreamHistoryHoldsTheSamplesTheRateCameFrom)
{
    constexpr double kWpDt = 0.2;
    VerifyHistory history;
    const VerifyRow r = row(verifyTwoStream(kWpDt, cpuDevice(), &history), "growth_rate_over_wp");
    const WrittenHistory written = writtenHistory(history);
    const std::vector<double>& t = written.columns.at("t_wp");
    const std::vector<double>& amplitude = written.columns.at("field_mode_V_per_m");
    const std::vector<double>& inFit = written.columns.at("in_fit");
    const double gamma = 1.0 / (2.0 * std::sqrt(2.0)); // ω_p/(2√2), the cold symmetric beams' fastest growth
    ASSERT_EQ(t.size(), std::size_t(std::ceil(9.0 / (gamma * kWpDt))) + 1);
    EXPECT_EQ(t.front(), 0.0);
    std::vector<double> ft, fy;
    for (std::size_t n = 0; n < t.size(); ++n) {
        EXPECT_NEAR(t[n], double(n) * kWpDt, 1e-9 * t.back());
        EXPECT_EQ(inFit[n], t[n] >= 6.0 / gamma ? 1.0 : 0.0) << t[n];
        if (inFit[n] == 1.0) {
            ft.push_back(t[n]);
            fy.push_back(std::log(amplitude[n]));
        }
    }
    ASSERT_GT(ft.size(), 20u);
    EXPECT_NEAR(fy.back() - fy.front(), 3.0, 0.2);
    double mt = 0.0, my = 0.0;
    for (std::size_t i = 0; i < ft.size(); ++i) {
        mt += ft[i] / double(ft.size());
        my += fy[i] / double(ft.size());
    }
    double stt = 0.0, sty = 0.0;
    for (std::size_t i = 0; i < ft.size(); ++i) {
        stt += (ft[i] - mt) * (ft[i] - mt);
        sty += (ft[i] - mt) * (fy[i] - my);
    }
    EXPECT_NEAR(sty / stt, r.measured, 1e-7 * r.measured);
    EXPECT_NEAR(written.fit.at("fitted_rate"), r.measured, 1e-8 * r.measured);
    EXPECT_NEAR(written.fit.at("expected_rate"), gamma, 1e-8);
    EXPECT_NEAR(written.fit.at("fit_start"), 6.0 / gamma, 1e-7);
}
