// The plasma's particle-in-cell step in GLSL compute shaders (GpuPic, float, EGL; Mesa llvmpipe in CI)
// against the CPU step in double (ElectrostaticPic), its bit-for-bit determinism, and the verify
// cases on the GPU against theory.
#include "physics/constants.h"
#include "components/aurora/tools/aurora_accuracy.h"
#include "components/plasma/gpu/gpu_limits.h"
#include "components/plasma/gpu/gpu_pic.h"
#include "components/plasma/gpu/gpu_poisson.h"
#include "components/plasma/gpu/gpu_verify_cases.h"
#include "components/plasma/live_pic.h"
#include "components/plasma/plasma.h"
#include "components/plasma/sheet_frames.h"
#include "components/plasma/simulation/discrete_laplacian.h"
#include "components/plasma/simulation/dispersion.h"
#include "components/plasma/simulation/electron_sheet.h"
#include "components/plasma/simulation/electrostatic_pic.h"
#include "components/plasma/simulation/fft_poisson_solver.h"
#include "components/plasma/simulation/particle_loading.h"
#include "components/plasma/simulation/particle_mesh.h"
#include "components/plasma/simulation/plasma_parameters.h"
#include "components/registry.h"
#include "components/roles/curtain_detail.h"
#include "gl/context.h"
#include "poisson_test_density.h"
#include "render/reference_ray.h"
#include "render/scene_samples.h"
#include "scene/scene.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <glm/geometric.hpp>
#include <glm/mat2x2.hpp>
#include <gtest/gtest.h>
#include <memory>
#include <random>
#include <stdexcept>
#include <string>
#include <tuple>

using namespace aurorawall;
using namespace aurorawall::components::plasma::simulation;
using namespace aurorawall::components::plasma::gpu;
using aurorawall::test::modesAndNoise;
using aurorawall::test::relativePotentialError;

namespace {

const std::string kShaders = std::string(AURORAWALL_SOURCE_DIR) + "/shaders";

constexpr double kDensity = 1e12;        // m⁻³
constexpr double kThermalSpeed = 4.19e5; // m/s: 1 eV electrons
constexpr double kWpDt = 0.2;

// A thermal plasma (random start, seed 3) with Δx = λ_D on cells^dimension cells, perCell particles
// per cell, in B = 5e-5 T along z (ω_c/ω_p = 0.16).
struct ThermalCase {
    PeriodicGrid grid;
    Particles electrons;
    glm::dvec3 magneticField{0.0, 0.0, 5e-5};
    double dt;
};

ThermalCase thermalCase(int dimension, int cells, int perCell)
{
    const double lambdaD = debyeLength(kThermalSpeed, kDensity);
    const PeriodicGrid grid(dimension, {cells, cells, cells}, {lambdaD, lambdaD, lambdaD});
    const int count = perCell * int(grid.nodeCount());
    return {grid, randomStart(grid, count, kDensity, kThermalSpeed, 3), {0.0, 0.0, 5e-5},
            kWpDt / plasmaFrequency(kDensity)};
}

struct Difference {
    double position = 0.0; // largest, in cells (across the periodic boundary: the shorter way)
    double velocity = 0.0; // largest, in thermal speeds
    bool finite = true;
};

Difference difference(const PeriodicGrid& grid, const std::vector<glm::dvec3>& gpuX, const std::vector<glm::dvec3>& gpuV,
                      const Particles& cpu)
{
    Difference d;
    for (std::size_t p = 0; p < gpuX.size(); ++p) {
        for (int a = 0; a < 3; ++a) {
            d.finite = d.finite && std::isfinite(gpuX[p][a]) && std::isfinite(gpuV[p][a]);
            const double box = grid.cells[a] * grid.spacing[a];
            double dx = std::abs(gpuX[p][a] - cpu.position[p][a]);
            dx = std::min(dx, box - dx);
            d.position = std::max(d.position, dx / grid.spacing[a]);
        }
        d.velocity = std::max(d.velocity, glm::length(gpuV[p] - cpu.velocity[p]) / kThermalSpeed);
    }
    return d;
}

Difference gpuAgainstCpu(int dimension, int cells, int perCell, int steps)
{
    const ThermalCase c = thermalCase(dimension, cells, perCell);
    ElectrostaticPic cpu(c.grid, c.electrons, c.magneticField, c.dt);
    GpuPic gpu(c.grid, c.electrons, c.magneticField, c.dt, kShaders);
    for (int n = 0; n < steps; ++n) {
        cpu.step();
        gpu.step();
    }
    const Difference d = difference(c.grid, gpu.positions(), gpu.velocities(), cpu.electrons());
    std::printf("%dD, %d^%d cells, %d per cell, %d steps: GPU float vs CPU double: max |dx| %.3g cells, "
                "max |dv| %.3g v_th\n",
                dimension, cells, dimension, perCell, steps, d.position, d.velocity);
    return d;
}

bool bitIdentical(const std::vector<glm::dvec3>& a, const std::vector<glm::dvec3>& b)
{
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(glm::dvec3)) == 0;
}

struct State {
    std::vector<glm::dvec3> positions, velocities;
    std::vector<double> chargeDensity;
};

State runOnGpu(const ThermalCase& c, int steps)
{
    GpuPic gpu(c.grid, c.electrons, c.magneticField, c.dt, kShaders);
    for (int n = 0; n < steps; ++n)
        gpu.step();
    return {gpu.positions(), gpu.velocities(), gpu.chargeDensity()};
}

} // namespace

// What float allows after `steps` steps on a box of `boxCells` cells along its longest axis
// (u = 2^-24): a position rounds by up to u·boxCells cells when it is stored, and moves by the
// velocity's rounding as much again, so the two runs part by at most 2·steps·u·boxCells cells,
// while they stay on the same side of every cell edge of the deposit (over 1.6 plasma periods a
// thermal plasma does not amplify a difference: the measured growth is linear). A velocity rounds
// by up to 16·u of itself in the Boris push's 16 operations a step, and its thermal spread reaches
// 4 v_th: at most 16·u·4·steps thermal speeds. Measured (llvmpipe, 50 steps): 3.2e-5 cells and
// 1.2e-5 v_th in 2D (32² cells, 8 per cell, bounds 1.9e-4 and 1.9e-4), 4.9e-5 and 9.1e-6 in 1D (64
// cells, 64 per cell, bounds 3.8e-4 and 1.9e-4), 1.6e-5 and 5.2e-6 in 3D (8³ cells, 4 per cell,
// bounds 4.8e-5 and 1.9e-4).
double positionBound(int steps, int boxCells) { return 2.0 * steps * std::ldexp(1.0, -24) * boxCells; }
double velocityBound(int steps) { return 16.0 * 4.0 * steps * std::ldexp(1.0, -24); }

TEST(PlasmaOnTheGpu, StepAgreesWithTheCpuStepIn2D)
{
    const auto context = gl::createContext(gl::Backend::Egl);
    const Difference d = gpuAgainstCpu(2, 32, 8, 50);
    EXPECT_TRUE(d.finite);
    EXPECT_LT(d.position, positionBound(50, 32));
    EXPECT_LT(d.velocity, velocityBound(50));
}

// The same text with PLASMA_DIMENSION 1 and 3.
TEST(PlasmaOnTheGpu, StepAgreesWithTheCpuStepIn1DAnd3D)
{
    const auto context = gl::createContext(gl::Backend::Egl);
    for (const auto& [dimension, cells, perCell] : {std::tuple{1, 64, 64}, std::tuple{3, 8, 4}}) {
        const Difference d = gpuAgainstCpu(dimension, cells, perCell, 50);
        EXPECT_TRUE(d.finite) << dimension << "D";
        EXPECT_LT(d.position, positionBound(50, cells)) << dimension << "D";
        EXPECT_LT(d.velocity, velocityBound(50)) << dimension << "D";
    }
}

// The fixed-point deposit against the CPU's double deposit, in units of one particle's charge
// density q/ΔV, and the ion background subtracted exactly. Each corner's weight rounds by at most half
// a quantum 2^-b (the last corner, taking the rest, by up to 2^d − 1 halves), and the float position
// moves a weight by up to d·u times the box in cells (u = 2^-24): a node is off by at most the number
// of particles around it (in its 2^d cells) times (2^d − 1)·2^-(b+1) + d·u·cells, the bound below,
// counted from the particles themselves (measured, llvmpipe, 8 per cell: 4.0e-6 in 1D at 2^-20,
// 5.0e-5 in 2D at 2^-17, 3.5e-5 in 3D at 2^-18, against bounds of 5.7e-5, 7.6e-4 and 1.3e-3). Σρ/Σ|ρ| came out
// 3.6e-17 at most: the sum of the integers is exactly 0, the rest is the final sum's rounding of
// N terms, held to N·2^-53.
double depositBound(const PeriodicGrid& grid, const Particles& electrons, int quantumBits)
{
    std::vector<int> perCell(grid.nodeCount(), 0);
    for (const glm::dvec3& x : electrons.position) {
        int cell[3] = {0, 0, 0};
        for (int a = 0; a < grid.dimension; ++a)
            cell[a] = std::clamp(int(std::floor(x[a] / grid.spacing[a])), 0, grid.cells[a] - 1);
        ++perCell[grid.index(cell[0], cell[1], cell[2])];
    }
    int most = 0; // particles in the 2^d cells around the busiest node
    for (int k = 0; k < grid.cells[2]; ++k)
        for (int j = 0; j < grid.cells[1]; ++j)
            for (int i = 0; i < grid.cells[0]; ++i) {
                int around = 0;
                for (int corner = 0; corner < (1 << grid.dimension); ++corner)
                    around += perCell[grid.index(i - (corner & 1), j - ((corner >> 1) & 1), k - ((corner >> 2) & 1))];
                most = std::max(most, around);
            }
    const int corners = 1 << grid.dimension;
    return most * ((corners - 1) * std::ldexp(1.0, -(quantumBits + 1)) +
                   grid.dimension * std::ldexp(1.0, -24) * grid.cells[0]);
}

TEST(PlasmaOnTheGpu, FixedPointDepositAgreesWithTheDoubleDeposit)
{
    const auto context = gl::createContext(gl::Backend::Egl);
    for (int dimension : {1, 2, 3}) {
        const ThermalCase c = thermalCase(dimension, dimension == 3 ? 8 : 32, 8);
        const GpuPic gpu(c.grid, c.electrons, c.magneticField, c.dt, kShaders);
        const std::vector<double> cpu = depositChargeDensity(c.grid, c.electrons);
        const double particleDensity = kElementaryCharge * c.electrons.weight / c.grid.cellVolume();
        double largest = 0.0, sum = 0.0, sumAbs = 0.0;
        for (std::size_t i = 0; i < cpu.size(); ++i) {
            largest = std::max(largest, std::abs(gpu.chargeDensity()[i] - cpu[i]) / particleDensity);
            sum += gpu.chargeDensity()[i];
            sumAbs += std::abs(gpu.chargeDensity()[i]);
        }
        std::printf("%dD deposit, 2^-%d quanta: max |rho_gpu - rho_cpu| = %.3g q/dV; sum rho / sum |rho| = %.3g\n",
                    dimension, gpu.quantumBits(), largest, sum / sumAbs);
        const double bound = depositBound(c.grid, c.electrons, gpu.quantumBits());
        std::printf("  bound %.3g\n", bound);
        EXPECT_LT(largest, bound) << dimension << "D";
        EXPECT_LT(std::abs(sum) / sumAbs, double(cpu.size()) * std::ldexp(1.0, -53)) << dimension << "D";
    }
}

TEST(PlasmaOnTheGpu, QuantumIsChosenSoThatNodeSumsCannotOverflow)
{
    EXPECT_EQ(depositQuantumBits(8192, 1), 17);
    EXPECT_EQ(depositQuantumBits(65536, 2), 14);
    EXPECT_EQ(depositQuantumBits(1, 3), 20);
    EXPECT_EQ(depositQuantumBits(8134407, 3), 8);
    EXPECT_THROW(depositQuantumBits(8134408, 3), std::invalid_argument);
}

// Two runs in one context, and a run in a second context created after the first was destroyed
// (standing in for two ranks), give the same bits.
TEST(PlasmaOnTheGpu, RunsAreBitIdentical)
{
    const ThermalCase c = thermalCase(2, 32, 8);
    State first, second, third;
    {
        const auto context = gl::createContext(gl::Backend::Egl);
        first = runOnGpu(c, 40);
        second = runOnGpu(c, 40);
    }
    {
        const auto context = gl::createContext(gl::Backend::Egl);
        third = runOnGpu(c, 40);
    }
    EXPECT_TRUE(bitIdentical(first.positions, second.positions));
    EXPECT_TRUE(bitIdentical(first.velocities, second.velocities));
    EXPECT_EQ(first.chargeDensity, second.chargeDensity);
    EXPECT_TRUE(bitIdentical(first.positions, third.positions));
    EXPECT_TRUE(bitIdentical(first.velocities, third.velocities));
    EXPECT_EQ(first.chargeDensity, third.chargeDensity);
    // The runs moved the particles (a test that compares untouched buffers cannot fail).
    EXPECT_FALSE(bitIdentical(first.positions, [&] {
        std::vector<glm::dvec3> start;
        for (const glm::dvec3& x : c.electrons.position)
            start.push_back(glm::dvec3(glm::vec3(x)));
        return start;
    }()));
}

// Measured (llvmpipe, ω_pΔt = 0.2, ω_cΔt = 1): langmuir 1.55e-5 (the CPU in double 4.7e-6: float
// adds 1.1e-5), langmuir-2d on 64² 2.41e-3 (the grid's dispersion, as on the CPU), the Boris rotation
// 1.4e-8 and the speed's largest change 5.3e-6 over 1000 steps (float rounding, a random walk of
// ~6e-8 per step), the E×B drift 1.5e-8 and 1.1e-8 along E. The test particle's bounds, from
// borisVelocity's operations in float (u = 2^-24):
// - t = B·(q/m·Δt/2) from three float inputs and two products, 5u; s = 2t/(1 + t²), 8u more. The
//   rotation 2 atan|t| errs by at most 5u of itself (d ln θ/d ln t ≤ 1), s's mismatch by 8u, and each
//   step's component roundings (vMinus, the two crosses and sums: within 6u of |v|) turn the stored
//   velocity by at most 2·6u: the mean angle per step within (13 + 12/θ)u relative;
// - |v|: the rotation keeps it exactly when s = 2t/(1 + t²); s's 8u moves it by 8u·2t/√(1 + t²) ≤ 8u,
//   the roundings by 10u: 18u a step, over 1000 steps at most 18000u;
// - the E×B drift, the centre of the velocities' circle: the fixed point moves with the inputs' and
//   t's rounding (10u), and each circumcentre, from three velocities within 6u of their length (at
//   most twice the drift) and θ ≈ 0.93 rad apart, by at most 4 times that: 58u of E/B, along E×B and
//   along E.
// The Langmuir frequencies are fits to an oscillation with the fixed-point deposit's noise and the
// float positions in it, whose worst case says nothing of the fit: their tolerances (1e-4 of theory,
// 15% of the dispersion) are measured, not derived.
TEST(PlasmaOnTheGpu, VerifyCasesAgreeWithTheory)
{
    const auto context = gl::createContext(gl::Backend::Egl);
    const auto measured = [](const std::vector<VerifyRow>& rows, const std::string& name) {
        for (const VerifyRow& row : rows)
            if (row.parameter == name)
                return row;
        ADD_FAILURE() << "no row " << name;
        return VerifyRow{};
    };
    const VerifyRow langmuir = measured(verifyLangmuir(kWpDt, GpuPicDevice(kShaders)), "omega_over_wp");
    const VerifyRow langmuir2D = measured(verifyLangmuir2D(kWpDt, 64, GpuPicDevice(kShaders)), "omega_over_wp");
    const std::vector<VerifyRow> boris = verifyBoris(1.0, 1000, GpuPicDevice(kShaders));
    const std::vector<VerifyRow> exb = verifyExB(1.0, GpuPicDevice(kShaders));
    std::printf("langmuir %.3g, langmuir-2d (64^2) %.3g, boris %.3g / %.3g, exb %.3g / %.3g\n",
                langmuir.relativeError(), langmuir2D.relativeError(),
                measured(boris, "rotation_per_step_rad").relativeError(),
                measured(boris, "max_relative_speed_change").relativeError(),
                measured(exb, "drift_along_ExB_over_E_over_B").relativeError(),
                measured(exb, "drift_along_E_over_E_over_B").relativeError());
    EXPECT_LT(langmuir.relativeError(), 1e-4);
    // 64² cells: the error is the grid's dispersion −(|k|Δx)²/8 = −2.41e-3, as on the CPU.
    const double kDx = std::sqrt(2.0) * 2.0 * aurorawall::physics::kPi / 64.0;
    const double dispersion = -kDx * kDx / 8.0;
    EXPECT_NEAR((langmuir2D.measured - *langmuir2D.expected) / *langmuir2D.expected, dispersion, 0.15 * -dispersion);
    const double u = std::ldexp(1.0, -24), theta = borisRotationPerStep(1.0);
    EXPECT_LT(measured(boris, "rotation_per_step_rad").relativeError(), (13.0 + 12.0 / theta) * u);
    EXPECT_LT(measured(boris, "max_relative_speed_change").relativeError(), 1000 * 18.0 * u);
    EXPECT_LT(measured(exb, "drift_along_ExB_over_E_over_B").relativeError(), 58.0 * u);
    EXPECT_LT(measured(exb, "drift_along_E_over_E_over_B").relativeError(), 58.0 * u);
}

namespace {

std::vector<double> solveOnGpu(const PeriodicGrid& grid, GpuPoissonMethod method, const std::vector<double>& rho,
                               int sweeps)
{
    GpuPoisson gpu(grid, method, kShaders);
    gpu.setChargeDensity(rho);
    gpu.solve(sweeps);
    return gpu.potential();
}

} // namespace

// Red-black SOR with ω = 2/(1 + √(1 − μ₁²)) shrinks the slowest error by about ω − 1 per sweep
// (0.87 on 64², 0.80 on 32³): picSorSweeps (10^-6) is 100 sweeps on 64² and 61 on 32³. Twice that
// many reach float rounding: the potential and the residual within floatPoissonBounds (measured on
// llvmpipe: 3.7e-7 and 1.9e-7 against bounds near 1e-3; NVIDIA H200: 4.8e-6 on 32³). The rate is
// checked only where the error is far above that bound: 10 and 20 sweeps from φ = 0, whose ratio
// (ω − 1)^10 is 0.25 and 0.10 once the slowest mode dominates; held below 0.5.
TEST(PlasmaPoissonOnTheGpu, RedBlackSorConvergesToTheFftPotential)
{
    const auto context = gl::createContext(gl::Backend::Egl);
    for (const PeriodicGrid& grid :
         {PeriodicGrid(2, {64, 64, 1}, {1.0, 1.0, 1.0}), PeriodicGrid(3, {32, 32, 32}, {1.0, 1.0, 1.0})}) {
        const std::vector<double> rho = modesAndNoise(grid);
        const std::vector<double> exact = FftPoissonSolver(grid).solve(rho);
        const test::FloatPoissonBounds bounds = test::floatPoissonBounds(grid, rho, exact);
        const int sweeps = 2 * picSorSweeps(grid);
        const std::vector<double> phi = solveOnGpu(grid, GpuPoissonMethod::RedBlackSor, rho, sweeps);
        const double error = relativePotentialError(phi, exact), residual = poissonResidual(grid, rho, phi);
        const double ten = relativePotentialError(solveOnGpu(grid, GpuPoissonMethod::RedBlackSor, rho, 10), exact);
        const double twenty = relativePotentialError(solveOnGpu(grid, GpuPoissonMethod::RedBlackSor, rho, 20), exact);
        std::printf("%dD, %d cells per axis, omega %.4f, %d sweeps: potential error %.3g (bound %.3g), residual %.3g "
                    "(bound %.3g); 10 and 20 sweeps: %.3g, %.3g\n",
                    grid.dimension, grid.cells[0], sorOverRelaxation(grid), sweeps, error, bounds.potential, residual,
                    bounds.residual, ten, twenty);
        EXPECT_LT(error, bounds.potential);
        EXPECT_LT(residual, bounds.residual);
        ASSERT_GT(twenty, 10.0 * bounds.potential);
        EXPECT_LT(twenty, 0.5 * ten);
    }
}

// Jacobi from φ = 0 on the longest wave alone, ρ ∝ cos(2πx/L): φ_m = (1 − μ^m) φ, so after 20
// sweeps the relative error is μ^20 with μ = Σ_d cos(2πk_d/n_d)/Δ_d² / Σ_d 1/Δ_d²: 0.9529329 on
// 64², 0.8794047 on 32³. In float each sweep rounds each node by up to (2d + 2)·u of max|φ| (u =
// 2^-24), which the sweeps after it carry along without growth (|μ| ≤ 1): after m sweeps at most
// m·(2d + 2)·u·max|φ|, relative to the cosine's RMS √2 times that: 1.0e-5 on 64², 1.4e-5 on 32³
// (measured within 2e-9 and 1e-8).
double jacobiBound(const PeriodicGrid& grid, int sweeps)
{
    return sweeps * (2.0 * grid.dimension + 2.0) * std::ldexp(1.0, -24) * std::sqrt(2.0);
}

TEST(PlasmaPoissonOnTheGpu, JacobiDampsTheLongestWaveAsTheClosedFormSays)
{
    const auto context = gl::createContext(gl::Backend::Egl);
    for (const PeriodicGrid& grid :
         {PeriodicGrid(2, {64, 64, 1}, {1.0, 1.0, 1.0}), PeriodicGrid(3, {32, 32, 32}, {1.0, 1.0, 1.0})}) {
        std::vector<double> longest(grid.nodeCount()), checkerboard(grid.nodeCount());
        for (int k = 0; k < grid.cells[2]; ++k)
            for (int j = 0; j < grid.cells[1]; ++j)
                for (int i = 0; i < grid.cells[0]; ++i) {
                    longest[grid.index(i, j, k)] = kVacuumPermittivity * std::cos(2.0 * aurorawall::physics::kPi * i / grid.cells[0]);
                    checkerboard[grid.index(i, j, k)] = kVacuumPermittivity * ((i + j + k) % 2 == 0 ? 1.0 : -1.0);
                }
        const FftPoissonSolver fft(grid);
        const double expected = std::pow(jacobiFactor(grid, 1, 0, 0), kPicJacobiSweeps);
        const double measured = relativePotentialError(
            solveOnGpu(grid, GpuPoissonMethod::Jacobi, longest, kPicJacobiSweeps), fft.solve(longest));
        const double checkerboardError = relativePotentialError(
            solveOnGpu(grid, GpuPoissonMethod::Jacobi, checkerboard, kPicJacobiSweeps), fft.solve(checkerboard));
        std::printf("%dD, %d cells per axis: Jacobi %d sweeps: longest wave's error %.7f, mu^%d = %.7f; "
                    "checkerboard's error %.4f; differences %.2g, %.2g\n",
                    grid.dimension, grid.cells[0], kPicJacobiSweeps, measured, kPicJacobiSweeps, expected,
                    checkerboardError, measured - expected, checkerboardError - 1.0);
        EXPECT_NEAR(measured, expected, jacobiBound(grid, kPicJacobiSweeps));
        // The checkerboard (−1)^(i+j+k), μ = −1, flips every sweep: after an even number from 0,
        // φ_m = (1 − (−1)^m) φ = 0 and the error is 1 (measured 1 + 1.2e-7 at most), within the
        // same bound (its max is its RMS).
        EXPECT_NEAR(checkerboardError, 1.0, jacobiBound(grid, kPicJacobiSweeps));
    }
}

TEST(PlasmaPoissonOnTheGpu, SolvesAreBitIdentical)
{
    const auto context = gl::createContext(gl::Backend::Egl);
    const PeriodicGrid grid(2, {32, 32, 1}, {1.0, 1.0, 1.0});
    const std::vector<double> rho = modesAndNoise(grid);
    for (const GpuPoissonMethod method : {GpuPoissonMethod::Jacobi, GpuPoissonMethod::RedBlackSor}) {
        const std::vector<double> a = solveOnGpu(grid, method, rho, 30), b = solveOnGpu(grid, method, rho, 30);
        EXPECT_EQ(std::memcmp(a.data(), b.data(), a.size() * sizeof(double)), 0);
    }
    const ThermalCase c = thermalCase(2, 16, 8);
    const auto run = [&c] {
        GpuPic gpu(c.grid, c.electrons, c.magneticField, c.dt, kShaders, glm::dvec3(0.0), GpuPicSolver::RedBlackSor);
        for (int n = 0; n < 10; ++n)
            gpu.step();
        return std::make_pair(gpu.positions(), gpu.velocities());
    };
    const auto first = run(), second = run();
    EXPECT_TRUE(bitIdentical(first.first, second.first));
    EXPECT_TRUE(bitIdentical(first.second, second.second));
}

TEST(PlasmaPoissonOnTheGpu, RedBlackSorAndMultigridNeedEvenCellCounts)
{
    const auto context = gl::createContext(gl::Backend::Egl);
    EXPECT_THROW(GpuPoisson(PeriodicGrid(2, {33, 32, 1}, {1.0, 1.0, 1.0}), GpuPoissonMethod::RedBlackSor, kShaders),
                 std::invalid_argument);
    EXPECT_THROW(GpuPoisson(PeriodicGrid(3, {8, 8, 5}, {1.0, 1.0, 1.0}), GpuPoissonMethod::Multigrid, kShaders),
                 std::invalid_argument);
    EXPECT_NO_THROW(GpuPoisson(PeriodicGrid(2, {33, 32, 1}, {1.0, 1.0, 1.0}), GpuPoissonMethod::Jacobi, kShaders));
}

// langmuir-2d on 32² with the step's multigrid (kPicMultigridCycles V-cycles per step from the
// previous step's φ): the frequency's error is the grid's dispersion −(|k|Δx)²/8 = −9.64e-3 as with
// the FFT, held to the same 15%. Against the same run with fft-cpu, whose φ is exact but for its
// rounding to float (u), only the solve differs: six V-cycles from the previous step's φ, which moves
// by ω_pΔt = 0.2 of itself a step, reach float (a factor 30 a cycle), so the multigrid's φ is within
// floatPoissonBounds of the exact one for the wave's density, a cosine along the diagonal. A relative
// error ε of the field the wave feels moves ω² by ε at most, ω by ε/2. Measured −9.6378e-3 against
// the FFT's −9.6385e-3, 7.5e-7 apart (red-black SOR, not run here for its cost, 1.6e-8).
TEST(PlasmaPoissonOnTheGpu, LangmuirWithConvergingSolversAgreesWithTheory)
{
    const auto context = gl::createContext(gl::Backend::Egl);
    const auto omega = [](GpuPicSolver solver) {
        for (const VerifyRow& row : verifyLangmuir2D(kWpDt, 32, GpuPicDevice(kShaders, solver)))
            if (row.parameter == "omega_over_wp")
                return (row.measured - *row.expected) / *row.expected;
        ADD_FAILURE() << "no omega_over_wp";
        return 0.0;
    };
    const double fft = omega(GpuPicSolver::FftCpu);
    const double kDx = std::sqrt(2.0) * 2.0 * aurorawall::physics::kPi / 32.0;
    const double dispersion = -kDx * kDx / 8.0;
    const PeriodicGrid grid(2, {32, 32, 1}, {1.0 / 32.0, 1.0 / 32.0, 1.0});
    std::vector<double> wave(grid.nodeCount());
    for (int j = 0; j < 32; ++j)
        for (int i = 0; i < 32; ++i)
            wave[grid.index(i, j, 0)] = kVacuumPermittivity * std::cos(2.0 * aurorawall::physics::kPi * (i + j) / 32.0);
    const double bound = 0.5 * (test::floatPoissonBounds(grid, wave, FftPoissonSolver(grid).solve(wave)).potential +
                                std::ldexp(1.0, -24));
    for (const GpuPicSolver solver : {GpuPicSolver::Multigrid}) {
        const double converged = omega(solver);
        std::printf("langmuir-2d 32^2: relative frequency error %.6g, with fft-cpu %.6g, difference %.3g "
                    "(bound %.3g)\n",
                    converged, fft, converged - fft, bound);
        EXPECT_NEAR(converged, dispersion, 0.15 * -dispersion);
        EXPECT_NEAR(converged, fft, bound);
    }
}

namespace {

// E = −∇φ by central differences (the node field's), in double.
std::vector<glm::dvec3> centralField(const PeriodicGrid& grid, const std::vector<double>& phi)
{
    std::vector<glm::dvec3> field(grid.nodeCount(), glm::dvec3(0.0));
    for (int j = 0; j < grid.cells[1]; ++j)
        for (int i = 0; i < grid.cells[0]; ++i) {
            glm::dvec3& e = field[grid.index(i, j, 0)];
            e.x = (phi[grid.index(i - 1, j, 0)] - phi[grid.index(i + 1, j, 0)]) / (2.0 * grid.spacing[0]);
            e.y = (phi[grid.index(i, j - 1, 0)] - phi[grid.index(i, j + 1, 0)]) / (2.0 * grid.spacing[1]);
        }
    return field;
}

double fieldNorm(const std::vector<glm::dvec3>& v)
{
    double sum = 0.0;
    for (const glm::dvec3& e : v)
        sum += glm::dot(e, e);
    return std::sqrt(sum);
}

// Red-black SOR sweeps from φ = 0 in double on a 2D grid, as poisson_sweep.comp's pass 3, and for
// each sweep the L2 norm over the nodes of the size its float roundings act on: a node's update
// rounds by at most 14u (the Jacobi value's 2d + 4 roundings, the source's 3, ω(φ_GS − φ) + φ's 3)
// of 2(the largest |φ| among the node and its neighbours, before and after) + |s|/D, D = Σ_d 2/Δ_d².
struct Swept {
    std::vector<double> phi;
    std::vector<double> roundingNorms; // per sweep, without the factor 14u
};

Swept sorSweeps(const PeriodicGrid& grid, const std::vector<double>& rho, int sweeps)
{
    double mean = 0.0;
    for (double r : rho)
        mean += r;
    mean /= double(rho.size());
    const double omega = sorOverRelaxation(grid), ix = 1.0 / (grid.spacing[0] * grid.spacing[0]),
                 iy = 1.0 / (grid.spacing[1] * grid.spacing[1]), diagonal = 2.0 * ix + 2.0 * iy;
    Swept r{std::vector<double>(rho.size(), 0.0), {}};
    std::vector<double>& phi = r.phi;
    for (int sweep = 0; sweep < sweeps; ++sweep) {
        double squares = 0.0;
        for (int colour = 0; colour < 2; ++colour)
            for (int j = 0; j < grid.cells[1]; ++j)
                for (int i = 0; i < grid.cells[0]; ++i) {
                    if ((i + j) % 2 != colour)
                        continue;
                    const std::size_t n = grid.index(i, j, 0);
                    const std::size_t around[4] = {grid.index(i - 1, j, 0), grid.index(i + 1, j, 0),
                                                   grid.index(i, j - 1, 0), grid.index(i, j + 1, 0)};
                    const double source = (rho[n] - mean) / kVacuumPermittivity;
                    const double gs = ((phi[around[0]] + phi[around[1]]) * ix + (phi[around[2]] + phi[around[3]]) * iy +
                                       source) / diagonal;
                    double largest = std::abs(phi[n]);
                    for (std::size_t k : around)
                        largest = std::max(largest, std::abs(phi[k]));
                    phi[n] += omega * (gs - phi[n]);
                    largest = std::max(largest, std::abs(phi[n]));
                    const double size = 2.0 * largest + std::abs(source) / diagonal;
                    squares += size * size;
                }
        r.roundingNorms.push_back(std::sqrt(squares));
    }
    return r;
}

// ‖∇G^k‖₂ for k < m, G red-black SOR's iteration matrix on a 2D grid, ∇ the central-difference
// field: on the red and the black part of each Fourier mode, whose Jacobi factor is μ, G is
// B = [[1 − ω, ωμ], [ωμ(1 − ω), 1 − ω + ω²μ²]] (a red half-sweep, then a black one reading it) and
// ∇ exchanges the two parts times |∇|'s symbol (Σ_d sin²(2πk_d/n_d)/Δ_d²)^½, which is 0 on the
// constant mode; so ‖∇G^k‖ is the largest over the modes of the symbol times ‖B^k‖₂.
std::vector<double> sorFieldPowers(const PeriodicGrid& grid, int sweeps)
{
    const double omega = sorOverRelaxation(grid);
    std::vector<double> powers(std::size_t(sweeps), 0.0);
    for (int b = 0; b < grid.cells[1]; ++b)
        for (int a = 0; a < grid.cells[0]; ++a) {
            const double mu = jacobiFactor(grid, a, b, 0);
            const double symbol = std::hypot(std::sin(2.0 * aurorawall::physics::kPi * a / grid.cells[0]) / grid.spacing[0],
                                             std::sin(2.0 * aurorawall::physics::kPi * b / grid.cells[1]) / grid.spacing[1]);
            const glm::dmat2 step(1.0 - omega, omega * mu * (1.0 - omega), omega * mu,
                                  1.0 - omega + omega * omega * mu * mu);
            glm::dmat2 power(1.0);
            for (int k = 0; k < sweeps; ++k) {
                // The 2-norm of a 2×2 matrix: the square root of the largest eigenvalue of MᵀM.
                const glm::dmat2 m = glm::transpose(power) * power;
                const double trace = m[0][0] + m[1][1], det = m[0][0] * m[1][1] - m[0][1] * m[1][0];
                const double norm = std::sqrt(0.5 * trace + std::sqrt(std::max(0.25 * trace * trace - det, 0.0)));
                powers[std::size_t(k)] = std::max(powers[std::size_t(k)], symbol * norm);
                power = step * power;
            }
        }
    return powers;
}

} // namespace

// The GPU solvers' source comes from the deposit's node sums on the GPU, not from the read-back:
// the first field of a thermal plasma (32², 8 per cell, deposited at 2^-14 of a particle) with SOR
// (picSorSweeps, 50 sweeps from φ = 0) against the exact one of fft-cpu, relative L2 difference.
// Bound: the sweeps' own error, the same sweeps in double from the same deposit (the truncation, near
// 1e-6 by design), plus float's: the roundings of sweep j (sorSweeps) carried into the field by
// ∇G^(m−j) (sorFieldPowers); fft-cpu's φ rounded to float, u of itself, at most √d/Δ times that in
// the field; the field's own difference and division, 6u of it, on both. Measured 3.8e-6, the
// truncation 3.77e-6.
TEST(PlasmaPoissonOnTheGpu, SorFieldFromTheDepositAgreesWithTheFftField)
{
    const auto context = gl::createContext(gl::Backend::Egl);
    const ThermalCase c = thermalCase(2, 32, 8);
    const auto gpuPic = [&c](GpuPicSolver solver) {
        return std::make_unique<GpuPic>(c.grid, c.electrons, c.magneticField, c.dt, kShaders, glm::dvec3(0.0), solver);
    };
    const std::unique_ptr<GpuPic> sorPic = gpuPic(GpuPicSolver::RedBlackSor), fftPic = gpuPic(GpuPicSolver::FftCpu);
    const std::vector<glm::dvec3> sor = sorPic->nodeField(), fft = fftPic->nodeField();
    double difference = 0.0, norm = 0.0;
    for (std::size_t i = 0; i < fft.size(); ++i) {
        difference += glm::dot(sor[i] - fft[i], sor[i] - fft[i]);
        norm += glm::dot(fft[i], fft[i]);
    }
    const double relative = std::sqrt(difference / norm);

    const double u = std::ldexp(1.0, -24);
    const int sweeps = picSorSweeps(c.grid);
    const std::vector<double>& rho = fftPic->chargeDensity();
    const std::vector<double> exact = FftPoissonSolver(c.grid).solve(rho);
    const std::vector<glm::dvec3> exactField = centralField(c.grid, exact);
    const Swept swept = sorSweeps(c.grid, rho, sweeps);
    const std::vector<glm::dvec3> sweptField = centralField(c.grid, swept.phi);
    std::vector<glm::dvec3> truncation(exactField.size());
    for (std::size_t i = 0; i < truncation.size(); ++i)
        truncation[i] = sweptField[i] - exactField[i];
    const std::vector<double> powers = sorFieldPowers(c.grid, sweeps);
    double sorRounding = 0.0;
    for (int j = 0; j < sweeps; ++j)
        sorRounding += powers[std::size_t(sweeps - 1 - j)] * 14.0 * u * swept.roundingNorms[std::size_t(j)];
    double phiNorm = 0.0;
    for (double p : exact)
        phiNorm += p * p;
    const double fftRounding = std::sqrt(2.0) / c.grid.spacing[0] * u * std::sqrt(phiNorm);
    const double truncated = fieldNorm(truncation) / fieldNorm(exactField);
    const double bound = truncated + (sorRounding + fftRounding) / fieldNorm(exactField) + 12.0 * u;
    std::printf("first field, 32^2: SOR (%d sweeps) against fft-cpu: %.3g (bound %.3g: the sweeps' own %.3g)\n", sweeps,
                relative, bound, truncated);
    EXPECT_LT(relative, bound);
}

// Multigrid V-cycles (red-black Gauss–Seidel 2 + 2, full weighting, linear prolongation; 5 levels
// on 64², 4 on 32³, 7 on 256², 5 on 64³) from φ = 0 shrink the error by a factor of about 30 (2D)
// and 16 (3D) a cycle (measured, llvmpipe: 3.3e-2, 1.1e-3, 3.8e-5 after 1–3 cycles on 64²) until
// float rounding. kPicMultigridCycles = 6 reach floatPoissonBounds. The rate is checked only while
// the error is far above the bound: the first cycle takes the error from 1 (φ = 0) below 0.1 (on
// 256² the bound, 7e-3, is within a factor 10 of that, so there only below 10 bounds). The cycles
// run once read back after each and once in one batch, bit-identically: on NVIDIA, where commands
// run asynchronously, the batch stalled at 4.1e-3 (64³) and grew from 3.4e-2 to 9.3e-2 (256²) while
// the coarse corrections were cleared by an upload unordered with the shaders.
TEST(PlasmaPoissonOnTheGpu, MultigridConvergesToTheFftPotential)
{
    const auto context = gl::createContext(gl::Backend::Egl);
    for (const PeriodicGrid& grid :
         {PeriodicGrid(2, {64, 64, 1}, {1.0, 1.0, 1.0}), PeriodicGrid(3, {32, 32, 32}, {1.0, 1.0, 1.0}),
          PeriodicGrid(2, {256, 256, 1}, {1.0, 1.0, 1.0}), PeriodicGrid(3, {64, 64, 64}, {1.0, 1.0, 1.0})}) {
        const std::vector<double> rho = modesAndNoise(grid);
        const std::vector<double> exact = FftPoissonSolver(grid).solve(rho);
        const test::FloatPoissonBounds bounds = test::floatPoissonBounds(grid, rho, exact);
        GpuPoisson gpu(grid, GpuPoissonMethod::Multigrid, kShaders);
        gpu.setChargeDensity(rho);
        std::vector<double> errors;
        for (int cycle = 1; cycle <= kPicMultigridCycles; ++cycle) {
            gpu.solve(1);
            const std::vector<double> phi = gpu.potential();
            errors.push_back(relativePotentialError(phi, exact));
            std::printf("%dD, %d cells per axis, %d levels, %d V-cycles: potential error %.3g (bound %.3g), "
                        "residual %.3g (bound %.3g)\n",
                        grid.dimension, grid.cells[0], gpu.levelCount(), cycle, errors.back(), bounds.potential,
                        poissonResidual(grid, rho, phi), bounds.residual);
        }
        EXPECT_LT(errors[0], std::max(0.1, 10.0 * bounds.potential));
        EXPECT_LT(errors.back(), bounds.potential);
        EXPECT_LT(poissonResidual(grid, rho, gpu.potential()), bounds.residual);
        const std::vector<double> batch = solveOnGpu(grid, GpuPoissonMethod::Multigrid, rho, kPicMultigridCycles);
        const std::vector<double> phi = gpu.potential();
        EXPECT_EQ(std::memcmp(batch.data(), phi.data(), phi.size() * sizeof(double)), 0);
    }
}

namespace {

// The row of a verify case with an expected value and this parameter, or (for the heating rate) the
// row of that parameter.
VerifyRow rowOf(const std::vector<VerifyRow>& rows, const std::string& parameter)
{
    for (const VerifyRow& r : rows)
        if (r.parameter == parameter)
            return r;
    ADD_FAILURE() << "no row " << parameter;
    return {};
}

} // namespace

// The diagonal wave on 16³ (the command uses 32³): the leapfrog relation times the grid's dispersion
// 1 − (|k|Δx)²/8, |k|Δx = √3·2π/16, as on the CPU. Measured (llvmpipe, ω_pΔt = 0.2): GPU −5.6734e-2,
// CPU −5.6719e-2, the dispersion −5.783e-2; the GPU's float 1.5e-5 from the CPU's double (on 32³
// 3.1e-5; 1D: 1.1e-5). Held to 15% of the dispersion, as on the CPU, and to 1e-4 of the CPU.
TEST(PlasmaOnTheGpu, Langmuir3DAgreesWithTheCpuAndTheGridDispersion)
{
    const auto context = gl::createContext(gl::Backend::Egl);
    const VerifyRow gpu = rowOf(verifyLangmuir3D(kWpDt, 16, GpuPicDevice(kShaders)), "omega_over_wp");
    const VerifyRow cpu = rowOf(verifyLangmuir3D(kWpDt, 16), "omega_over_wp");
    const double kDx = std::sqrt(3.0) * 2.0 * aurorawall::physics::kPi / 16.0;
    const double dispersion = -kDx * kDx / 8.0;
    std::printf("langmuir-3d 16^3: GPU %.6g, CPU %.6g, dispersion %.6g\n", gpu.measured / *gpu.expected - 1.0,
                cpu.measured / *cpu.expected - 1.0, dispersion);
    EXPECT_NEAR(gpu.measured / *gpu.expected - 1.0, dispersion, 0.15 * -dispersion);
    EXPECT_NEAR(gpu.measured, cpu.measured, 1e-4 * cpu.measured);
}

// Two-stream, the same quiet start on both devices: measured growth rates 3.1e-5 (CPU) and 5.7e-5
// (GPU) from theory, 2.6e-5 apart; with a 1e-7 seed the GPU's float rounding moved it by 2.9e-3, so
// the 1e-6 seed's share is about 3e-4. Held to 1e-3 of theory and of the CPU.
TEST(PlasmaOnTheGpu, TwoStreamGrowsAtTheColdRateAsOnTheCpu)
{
    const auto context = gl::createContext(gl::Backend::Egl);
    const VerifyRow gpu = rowOf(verifyTwoStream(kWpDt, GpuPicDevice(kShaders)), "growth_rate_over_wp");
    const VerifyRow cpu = rowOf(verifyTwoStream(kWpDt), "growth_rate_over_wp");
    std::printf("two-stream: GPU %.4g, CPU %.4g from theory\n", gpu.relativeError(), cpu.relativeError());
    EXPECT_LT(gpu.relativeError(), 1e-3);
    EXPECT_NEAR(gpu.measured, cpu.measured, 1e-3 * cpu.measured);
}

// Energy, a random start (chaotic: the devices' trajectories part after a few plasma periods, so
// only the drift's size compares): measured 0.23% (GPU) and 0.34% (CPU) over 200 plasma periods;
// held to 1%, as on the CPU.
TEST(PlasmaOnTheGpu, TotalEnergyDriftsLittle)
{
    const auto context = gl::createContext(gl::Backend::Egl);
    const VerifyRow drift = rowOf(verifyEnergy(kWpDt, GpuPicDevice(kShaders)), "relative_energy_drift");
    std::printf("energy: relative drift %.4g on the GPU\n", drift.measured);
    EXPECT_LT(std::abs(drift.measured), 1e-2);
    EXPECT_GT(std::abs(drift.measured), 0.0);
}

// Grid heating on the GPU (seed 1): measured 8.3e-7, 1.25e-4 and 2.92e-3 at Δx/λ_D = 0.5, 2 and 8
// (CPU 5.5e-6, 1.16e-4, 2.96e-3: at 0.5 both are the particles' noise, the CPU's seeds 1–6 scattering
// from −1.1e-6 to 5.5e-6). The CPU test's bounds, and at 8 within 10% of the CPU's rate (1.4% apart).
TEST(PlasmaOnTheGpu, GridHeatingGrowsWithTheSpacingAsOnTheCpu)
{
    const auto context = gl::createContext(gl::Backend::Egl);
    const GpuPicDevice gpu(kShaders);
    const auto rate = [&gpu](double dxOverDebye) {
        return rowOf(verifyHeating(kWpDt, dxOverDebye, 1, gpu), "heating_rate_over_wp").measured;
    };
    const double resolved = rate(0.5), coarse = rate(2.0), coarsest = rate(8.0);
    const double cpuCoarsest = rowOf(verifyHeating(kWpDt, 8.0, 1), "heating_rate_over_wp").measured;
    std::printf("heating on the GPU: %.3g, %.3g, %.3g (CPU at 8: %.3g)\n", resolved, coarse, coarsest, cpuCoarsest);
    EXPECT_LT(std::abs(resolved), 2e-5);
    EXPECT_GT(coarse, std::abs(resolved));
    EXPECT_GT(coarsest, coarse);
    EXPECT_NEAR(coarsest, cpuCoarsest, 0.1 * cpuCoarsest);
}

// Landau damping with 2^18 particles (the command: 2^20, 19 s on llvmpipe), the same quiet start on
// both devices. Measured: frequency 1.41815 on both (theory 1.415662: 1.8e-3; 8.6e-4 with 2^20), the
// damping rate −0.153384 (GPU) and −0.153373 (CPU) against −0.153360 (with 2^20 3.8e-3 off, with 2^16
// 7%: the particles' noise). Held to 3e-3 and 1e-2 of theory, and to 1e-3 of the CPU (measured 1e-6
// and 8e-5).
TEST(PlasmaOnTheGpu, LandauDampingAsOnTheCpu)
{
    const auto context = gl::createContext(gl::Backend::Egl);
    const std::vector<VerifyRow> gpu = verifyLandau(kWpDt, 0.5, 1 << 18, GpuPicDevice(kShaders));
    const std::vector<VerifyRow> cpu = verifyLandau(kWpDt, 0.5, 1 << 18);
    for (const char* name : {"frequency_over_wp", "damping_rate_over_wp"})
        std::printf("landau %s: GPU %.7g, CPU %.7g, theory %.7g\n", name, rowOf(gpu, name).measured,
                    rowOf(cpu, name).measured, *rowOf(cpu, name).expected);
    for (const char* name : {"frequency_over_wp", "damping_rate_over_wp"}) {
        const double gpuValue = rowOf(gpu, name).measured, cpuValue = rowOf(cpu, name).measured;
        EXPECT_NEAR(gpuValue, cpuValue, 1e-3 * std::abs(cpuValue)) << name;
    }
    EXPECT_LT(rowOf(gpu, "frequency_over_wp").relativeError(), 3e-3);
    EXPECT_LT(rowOf(gpu, "damping_rate_over_wp").relativeError(), 1e-2);
}

// Diocotron, the same lattice on both devices: measured 0.99% (GPU) and 0.89% (CPU) below the
// guiding-centre rate, 1.0e-3 of it apart (other seeds of the GPU run scattered by up to 0.6%). Held
// to 2% of theory, as on the CPU, and to 3e-3 of the CPU.
TEST(PlasmaOnTheGpu, DiocotronGrowsAsOnTheCpu)
{
    const auto context = gl::createContext(gl::Backend::Egl);
    const VerifyRow gpu = rowOf(verifyDiocotron(5.0, 0.1, GpuPicDevice(kShaders)), "growth_rate_over_wd");
    const VerifyRow cpu = rowOf(verifyDiocotron(5.0, 0.1), "growth_rate_over_wd");
    std::printf("diocotron: GPU %.4g, CPU %.4g below theory\n", gpu.relativeError(), cpu.relativeError());
    EXPECT_LT(gpu.relativeError(), 2e-2);
    EXPECT_NEAR(gpu.measured, cpu.measured, 3e-3 * *cpu.expected);
}

// The limits are checked before anything is made: the deposit's overflow bound (no GL needed), one
// dispatch's work groups and one storage block, each named with the numbers.
TEST(PlasmaOnTheGpu, RefusesCountsBeyondTheContextsLimits)
{
    const auto context = gl::createContext(gl::Backend::Egl);
    const PeriodicGrid line(1, {64, 1, 1}, {1.0, 1.0, 1.0});
    Particles tooMany;
    tooMany.position.resize(9000000);
    try {
        GpuPic pic(line, tooMany, glm::dvec3(0.0), 1e-9, kShaders);
        ADD_FAILURE() << "9000000 particles accepted";
    } catch (const std::invalid_argument& e) {
        EXPECT_STREQ(e.what(), "9000000 particles exceed the fixed-point deposit's limit of 8323580 in 1D "
                               "(32-bit node sums at 2^-8 of a particle)");
    }

    const GpuLimits limits = currentGpuLimits();
    std::printf("GL_MAX_COMPUTE_WORK_GROUP_COUNT x = %lld, GL_MAX_SHADER_STORAGE_BLOCK_SIZE = %lld\n",
                limits.maxWorkGroupsX, limits.maxStorageBlockBytes);
    EXPECT_GE(limits.maxWorkGroupsX, 65535);           // the GL 4.5 minimum
    EXPECT_GE(limits.maxStorageBlockBytes, 1LL << 27); // the GL 4.5 minimum
    // A grid of one node more than a dispatch along x covers (4194241 on llvmpipe).
    const long long nodes = limits.maxWorkGroupsX * 64 + 1;
    if (nodes <= (1LL << 30)) {
        const PeriodicGrid wide(1, {int(nodes), 1, 1}, {1.0, 1.0, 1.0});
        Particles one;
        one.position = {glm::dvec3(0.5, 0.5, 0.5)};
        one.velocity = {glm::dvec3(0.0)};
        const std::string expected = std::to_string(nodes) + " grid nodes need " +
                                     std::to_string(limits.maxWorkGroupsX + 1) +
                                     " work groups of 64, more than GL_MAX_COMPUTE_WORK_GROUP_COUNT x = " +
                                     std::to_string(limits.maxWorkGroupsX) + " (at most " +
                                     std::to_string(nodes - 1) + " grid nodes)";
        try {
            GpuPic pic(wide, one, glm::dvec3(0.0), 1e-9, kShaders);
            ADD_FAILURE() << nodes << " nodes accepted";
        } catch (const std::length_error& e) {
            EXPECT_EQ(e.what(), expected);
        }
        EXPECT_THROW(GpuPoisson(wide, GpuPoissonMethod::Jacobi, kShaders), std::length_error);
    }
    // One storage block: 65537 particles of 16 bytes in a 1 MiB block.
    try {
        requireFitsGpu({1LL << 20, 65535}, 65537, "particles", 64, 16);
        ADD_FAILURE() << "65537 particles fit 1 MiB";
    } catch (const std::length_error& e) {
        EXPECT_STREQ(e.what(), "65537 particles need a storage buffer of 1048592 bytes, more than "
                               "GL_MAX_SHADER_STORAGE_BLOCK_SIZE = 1048576 (at most 65536 particles)");
    }
    EXPECT_NO_THROW(requireFitsGpu({1LL << 20, 65535}, 65536, "particles", 64, 16));
}


// ---- The plasma component's simulation run live on the GPU (device = "gpu", LivePic) ----

namespace {

namespace component = aurorawall::components::plasma;

const std::string kSource = AURORAWALL_SOURCE_DIR;

// The strip of tests/app/data/plasma-seam.toml: 128 x 32 cells, 2048 electrons, 8 frames of 96 steps.
component::SheetFramesSpec seamStrip()
{
    return component::sheetFramesSpec(
        components::loadScene(kSource + "/tests/app/data/plasma-seam.toml").settings<component::Settings>());
}

component::LivePic liveStrip(const component::SheetFramesSpec& spec)
{
    return component::LivePic(
        sheetGrid(spec.sheet), sheetElectrons(spec.sheet), glm::dvec3(0.0, 0.0, spec.sheet.magneticFieldT),
        sheetTimeStep(spec.sheet),
        [spec](const PeriodicGrid& g, const Particles& e) { return component::sheetFrameDensity(spec, g, e); },
        kShaders);
}

bool sameBits(const std::vector<float>& a, const std::vector<float>& b)
{
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(float)) == 0;
}

} // namespace

// The texture of a step depends on the step alone: a run taken forward, back to an earlier step (a
// restart from the seeded start) and forward again gives, at each step, the bits of a fresh run
// stepped straight there; neighbouring steps differ.
TEST(PlasmaLive, SameStepSameBitsAfterJumpsBackAndForth)
{
    const auto context = gl::createContext(gl::Backend::Egl);
    const component::SheetFramesSpec spec = seamStrip();
    component::LivePic wandering = liveStrip(spec);
    EXPECT_TRUE(wandering.advanceTo(300));
    EXPECT_FALSE(wandering.advanceTo(300)); // the same step: nothing to do
    EXPECT_TRUE(wandering.advanceTo(100));  // back: a restart
    EXPECT_EQ(wandering.step(), 100);
    const std::vector<float> at100 = wandering.frame();
    EXPECT_TRUE(wandering.advanceTo(500));
    const std::vector<float> at500 = wandering.frame();
    for (const auto& [step, frame] : {std::pair<long, const std::vector<float>*>{100, &at100}, {500, &at500}}) {
        const auto secondContext = gl::createContext(gl::Backend::Egl);
        component::LivePic straight = liveStrip(spec);
        straight.advanceTo(step);
        EXPECT_TRUE(sameBits(straight.frame(), *frame)) << "step " << step;
        straight.advanceTo(step + 1);
        EXPECT_FALSE(sameBits(straight.frame(), *frame)) << "step " << step + 1;
    }
    EXPECT_THROW(wandering.advanceTo(-1), std::invalid_argument);
}

// The live run (float, fixed-point deposit) against the CPU frames (double) at the frames' steps, in
// units of the frame's peak. Frame 0: the electrons' positions rounded to float, each coordinate by u
// of itself (u = 2^-24), move a particle's CIC weights at the cell centres by at most
// u·(cells along + cells across), so a frame value by that times one particle's share times the
// particles around its centre (counted), and both frames' values round to float, u each (measured
// 7.2e-7, frameZeroBound). Before the roll-up (frames 1-4 of 8, the peak still below 1.2 of the
// straight strip's) the float round-off of every step is carried along by the growing mode: measured
// 3.8e-5, 8.5e-5, 2.3e-4, 6.3e-4, held to 2e-3; through the roll-up (frames 5-7) 5.7e-4, 2.9e-3,
// 6.3e-3, held to 2e-2. Those two are measured, not derived: the fixed-point deposit's rounding (up
// to 3.7e-4 of a particle's charge at a node, 2^-16 quanta) and the float push, carried by the
// diocotron growth and then the roll-up's mixing, bound in the worst case (every step's rounding
// aligned with the fastest growth) a difference far above these. The comparison sees a step's worth
// of motion: the live frame 4 against the CPU frame 3 differs by more than 2e-2.
double frameZeroBound(const component::SheetFramesSpec& spec, const components::roles::FluxFrames& cpu)
{
    const PeriodicGrid grid = sheetGrid(spec.sheet);
    const Particles electrons = sheetElectrons(spec.sheet);
    // The particles in each cell of the lattice moved back by half a cell (the deposit at the
    // centres), then the most in any 2 × 2 block: those whose weights reach one centre.
    std::vector<int> perCell(grid.nodeCount(), 0);
    for (const glm::dvec3& x : electrons.position) {
        int cell[2];
        for (int a = 0; a < 2; ++a) {
            const double shifted = x[a] / grid.spacing[a] - 0.5;
            cell[a] = int(std::floor(shifted - grid.cells[a] * std::floor(shifted / grid.cells[a])));
        }
        ++perCell[grid.index(cell[0], cell[1], 0)];
    }
    int most = 0;
    for (int j = 0; j < grid.cells[1]; ++j)
        for (int i = 0; i < grid.cells[0]; ++i)
            most = std::max(most, perCell[grid.index(i, j, 0)] + perCell[grid.index(i - 1, j, 0)] +
                                      perCell[grid.index(i, j - 1, 0)] + perCell[grid.index(i - 1, j - 1, 0)]);
    double peak = 0.0;
    for (int i = 0; i < cpu.nx * cpu.ny; ++i)
        peak = std::max(peak, double(cpu.flux[std::size_t(i)]));
    const double u = std::ldexp(1.0, -24);
    const double perKm = 1.0 / (spec.sheet.electronDensity * spec.sheet.thicknessM * 1e-3);
    const double share = electrons.weight / grid.cellVolume() * perKm; // one particle's whole weight
    return most * u * (grid.cells[0] + grid.cells[1]) * share / peak + 2.0 * u;
}
TEST(PlasmaLive, AgreesWithTheCpuFramesBeforeTheRollUp)
{
    const auto context = gl::createContext(gl::Backend::Egl);
    const component::SheetFramesSpec spec = seamStrip();
    const components::roles::FluxFrames cpu = component::simulateSheetFrames(spec);
    component::LivePic live = liveStrip(spec);
    const std::size_t texels = std::size_t(cpu.nx) * cpu.ny;
    const auto difference = [&](int cpuFrame) {
        double largest = 0.0, peak = 0.0;
        for (std::size_t i = 0; i < texels; ++i) {
            const double reference = cpu.flux[cpuFrame * texels + i];
            largest = std::max(largest, std::abs(double(live.frame()[i]) - reference));
            peak = std::max(peak, reference);
        }
        return largest / peak;
    };
    const double zeroBound = frameZeroBound(spec, cpu);
    for (int k = 0; k < spec.frames; ++k) {
        live.advanceTo(long(k) * spec.stepsPerFrame);
        const double d = difference(k);
        std::printf("frame %d (step %ld): largest difference %.3g of the peak%s\n", k, live.step(), d,
                    k == 0 ? (" (bound " + std::to_string(zeroBound) + ")").c_str() : "");
        EXPECT_LT(d, k == 0 ? zeroBound : k <= 4 ? 2e-3 : 2e-2) << "frame " << k;
        if (k == 4) {
            EXPECT_GT(difference(3), 2e-2);
        }
    }
}

// The curls rendered with the strip run live on the GPU against the double-precision CPU reference,
// which samples the CPU frames (tests/app/data/plasma-seam.toml at the renderer's finest settings, t =
// 60 s: detail phase 1, step 672, the last frame), at the 16 brightest pixels of the middle half of the
// view. Not at the arc's ends: there the curtain reaches past its end points by the detail's reach,
// which the live run takes as the strip's half width (its later steps are not known at start-up)
// and the CPU frames measure (2.4 km against 4 km here), so the live arc is longer by design. Tolerance:
// the frames' difference through the roll-up (up to 6.3e-3 of the peak, above) plus the march's own
// error (its discretization: max 3.0e-3 at the CPU frames' brightest pixels, tests/render/shader_steps_test.cpp)
// is 9.3e-3 where the brightest pixels sit near the peak; held to RMS 6e-3 and max 1.5e-2, measured, not
// derived: the frames' difference is itself measured (above), and the live frames are not the CPU's, so
// the float bound of PlasmaOnTheGpu.AgreesWithTheReference does not apply. Measured RMS 8.7e-4, max 2.9e-3 (the CPU
// frames' render: 1.0e-3 and 3.0e-3). The frames of a strip with one
// more wave put the reference off by far more (held above 0.1): the comparison sees the curls.
TEST(PlasmaLive, RenderAgreesWithTheReference)
{
    const std::unique_ptr<gl::Context> context = gl::createContext(gl::Backend::Egl);
    scene::Scene s = scene::withoutUnmodelled(components::loadScene(kSource + "/tests/app/data/plasma-seam.toml"));
    components::aurora::tools::applyFinestSettings(s);
    s.settings<component::Settings>().device = component::Settings::Device::Gpu;
    const accuracy::SceneView view = accuracy::sceneView(s, kSource + "/config/walls/single.toml", {64, 36});
    const io::Image gpu = accuracy::renderView(s, view, kShaders, 0).image;
    const double floor = 1.0 / (255.0 * s.exposure);
    // The middle half of the view: the arc's ends (near x = 10 and 53 of 64) lie outside it.
    std::vector<glm::ivec2> middle;
    for (int y = 0; y < gpu.height; ++y)
        for (int x = gpu.width / 4; x < 3 * gpu.width / 4; ++x)
            middle.emplace_back(x, y);
    std::vector<glm::ivec2> pixels = test::brightestFirst(gpu, middle);
    pixels.resize(16);
    const components::roles::FluxFrames frames = component::simulateSheetFrames(seamStrip());
    const render::ReferenceModel model(s, view.frame.timeS, components::roles::curtainDetailData(&frames));
    std::vector<glm::dvec3> values;
    for (const glm::ivec2& p : pixels)
        values.push_back(accuracy::pixelRadiance(gpu, p.x, p.y));
    const accuracy::RelativeError e = accuracy::relativeError(values, accuracy::referencePixels(model, view, pixels, 2), floor);
    std::printf("plasma live on the GPU (finest) vs CPU reference at the %zu brightest pixels: rms %.3g, max %.3g\n",
                e.pixels, e.rms, e.max);
    component::Settings other = s.settings<component::Settings>();
    other.seedMode += 1;
    const components::roles::FluxFrames otherFrames = component::simulateSheetFrames(component::sheetFramesSpec(other));
    const render::ReferenceModel otherModel(s, view.frame.timeS, components::roles::curtainDetailData(&otherFrames));
    const accuracy::RelativeError wrong =
        accuracy::relativeError(values, accuracy::referencePixels(otherModel, view, pixels, 2), floor);
    std::printf("against the frames of a strip with one more wave: rms %.3g\n", wrong.rms);
    EXPECT_EQ(e.pixels, pixels.size());
    EXPECT_LT(e.rms, 6e-3);
    EXPECT_LT(e.max, 1.5e-2);
    EXPECT_GT(wrong.rms, 0.1);
}


// A live simulation solves with the multigrid on a GPU where the cell counts are even, with the FFT
// on the CPU otherwise and on Mesa's CPU renderers (where the multigrid's small dispatches cost more).
TEST(PlasmaOnTheGpu, LiveSolverIsChosenForTheGridAndDevice)
{
    const PeriodicGrid even(2, {128, 32, 1}, {1.0, 1.0, 1.0}), odd(2, {128, 33, 1}, {1.0, 1.0, 1.0});
    EXPECT_EQ(preferredGpuPicSolver(even, "NVIDIA H200/PCIe/SSE2"), GpuPicSolver::Multigrid);
    EXPECT_EQ(preferredGpuPicSolver(odd, "NVIDIA H200/PCIe/SSE2"), GpuPicSolver::FftCpu);
    EXPECT_EQ(preferredGpuPicSolver(even, "llvmpipe (LLVM 15.0.6, 256 bits)"), GpuPicSolver::FftCpu);
}
