// Not a test: the cost of GpuPic's step phase by phase, and the error against the time of the Poisson
// solvers on the GPU (docs/PLASMA.md, "On the GPU" and "The solve on the GPU").
//
// Step: a thermal plasma (random start, Δx = λ_D) on 64³ cells with 2 particles per cell (524,288
// particles), and on 256² cells with 1 per cell, with each of the step's solvers; prints ns per
// particle per step for the push and the deposit and ms per field solve, the median over the timed
// steps after two untimed ones.
//
// Solvers: on 64², 256² and 64³ (Δ = 1 m) a charge density of three Fourier modes plus uniform noise
// of a tenth of their amplitude; the exact potential by FFT in double; each GPU solver from φ = 0 for
// a number of sweeps or V-cycles, once (after one untimed sweep), waited for with glFinish: the relative L2 error of the potential (mean
// removed) and of the central-difference field against the exact one, the relative Poisson residual
// of the float result (poissonResidual), and ms per solve (the FFT's: the median of three).
#include "components/plasma/gpu/gpu_pic.h"
#include "components/plasma/gpu/gpu_poisson.h"
#include "components/plasma/simulation/discrete_laplacian.h"
#include "components/plasma/simulation/fft_poisson_solver.h"
#include "components/plasma/simulation/particle_loading.h"
#include "components/plasma/simulation/plasma_parameters.h"
#include "gl/context.h"
#include "gl/functions.h"
#include "poisson_test_density.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

using namespace aurorawall;
using namespace aurorawall::components::plasma::simulation;
using namespace aurorawall::components::plasma::gpu;

namespace {

const std::string kShaders = std::string(AURORAWALL_SOURCE_DIR) + "/shaders";
using Clock = std::chrono::steady_clock;

double median(std::vector<double> values)
{
    std::sort(values.begin(), values.end());
    return values[values.size() / 2];
}

double millisecondsSince(Clock::time_point start)
{
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

const char* solverName(GpuPicSolver solver)
{
    return solver == GpuPicSolver::FftCpu      ? "fft-cpu"
           : solver == GpuPicSolver::Jacobi    ? "jacobi"
           : solver == GpuPicSolver::Multigrid ? "multigrid"
                                               : "sor";
}

void measureStep(int dimension, int cells, int perCell, int steps, GpuPicSolver solver)
{
    const double density = 1e12, thermalSpeed = 4.19e5;
    const double lambdaD = debyeLength(thermalSpeed, density);
    const PeriodicGrid grid(dimension, {cells, cells, cells}, {lambdaD, lambdaD, lambdaD});
    const int count = perCell * int(grid.nodeCount());
    GpuPic pic(grid, randomStart(grid, count, density, thermalSpeed, 1), glm::dvec3(0.0, 0.0, 5e-5),
               0.2 / plasmaFrequency(density), kShaders, glm::dvec3(0.0), solver);
    pic.step();
    pic.step();
    std::vector<double> push, deposit, solve, field;
    for (int n = 0; n < steps; ++n) {
        const StepTimes t = pic.timedStep();
        push.push_back(t.pushMs);
        deposit.push_back(t.depositMs);
        solve.push_back(t.solveMs);
        field.push_back(t.fieldMs);
    }
    const double ns = 1e6 / count;
    std::printf("%dD %d^%d cells, %d particles, solver %s: push (gather + Boris) %.1f ns/particle, deposit %.1f "
                "ns/particle, solve %.2f ms, field %.2f ms, step %.1f ms\n",
                dimension, cells, dimension, count, solverName(solver), median(push) * ns, median(deposit) * ns,
                median(solve), median(field), median(push) + median(deposit) + median(solve) + median(field));
}

double relativeL2(const std::vector<double>& approx, const std::vector<double>& exact)
{
    double difference = 0.0, norm = 0.0;
    for (std::size_t i = 0; i < exact.size(); ++i) {
        difference += (approx[i] - exact[i]) * (approx[i] - exact[i]);
        norm += exact[i] * exact[i];
    }
    return std::sqrt(difference / norm);
}

// The central-difference field, all components in one list.
std::vector<double> field(const PeriodicGrid& grid, const std::vector<double>& phi)
{
    std::vector<double> e;
    for (int k = 0; k < grid.cells[2]; ++k)
        for (int j = 0; j < grid.cells[1]; ++j)
            for (int i = 0; i < grid.cells[0]; ++i)
                for (int d = 0; d < grid.dimension; ++d) {
                    const int s[3] = {d == 0, d == 1, d == 2};
                    e.push_back((phi[grid.index(i - s[0], j - s[1], k - s[2])] -
                                 phi[grid.index(i + s[0], j + s[1], k + s[2])]) /
                                (2.0 * grid.spacing[d]));
                }
    return e;
}

void measureSolvers(int dimension, int cells, const std::vector<std::pair<GpuPoissonMethod, int>>& runs)
{
    const PeriodicGrid grid(dimension, {cells, cells, cells}, {1.0, 1.0, 1.0});
    const std::vector<double> rho = test::modesAndNoise(grid);
    FftPoissonSolver fft(grid);
    std::vector<double> exact, fftMs;
    for (int n = 0; n < 3; ++n) {
        const Clock::time_point start = Clock::now();
        exact = fft.solve(rho);
        fftMs.push_back(millisecondsSince(start));
    }
    const std::vector<double> exactField = field(grid, exact);
    const char* name = dimension == 2 ? "^2" : "^3";
    std::printf("%d%s,fft-cpu,-,0,0,%.2e,%.3g\n", cells, name, poissonResidual(grid, rho, exact), median(fftMs));
    for (const auto& [method, sweeps] : runs) {
        GpuPoisson gpu(grid, method, kShaders);
        gpu.setChargeDensity(rho);
        gpu.solve(1); // llvmpipe compiles a shader at its first dispatch: not part of the solve
        gpu.clearPotential();
        gl::glFinish();
        const Clock::time_point start = Clock::now();
        gpu.solve(sweeps);
        gl::glFinish();
        const double ms = millisecondsSince(start);
        const std::vector<double> phi = gpu.potential();
        std::printf("%d%s,%s,%d,%.3e,%.2e,%.2e,%.3g\n", cells, name,
                    method == GpuPoissonMethod::Jacobi        ? "jacobi"
                    : method == GpuPoissonMethod::Multigrid ? "multigrid"
                                                            : "sor",
                    sweeps,
                    test::relativePotentialError(phi, exact), relativeL2(field(grid, phi), exactField),
                    poissonResidual(grid, rho, phi), ms);
    }
}

} // namespace

int main()
{
    const auto context = gl::createContext(gl::Backend::Egl);
    for (const GpuPicSolver solver :
         {GpuPicSolver::FftCpu, GpuPicSolver::Jacobi, GpuPicSolver::RedBlackSor, GpuPicSolver::Multigrid}) {
        measureStep(3, 64, 2, 5, solver);
        measureStep(2, 256, 1, 10, solver);
    }
    std::printf("grid,solver,sweeps,potential_error,field_error,residual,ms\n");
    using M = GpuPoissonMethod;
    for (const int cells : {64, 256}) {
        const PeriodicGrid grid(2, {cells, cells, 1}, {1.0, 1.0, 1.0});
        measureSolvers(2, cells, {{M::Jacobi, 20}, {M::Jacobi, 200}, {M::RedBlackSor, 20},
                                  {M::RedBlackSor, picSorSweeps(grid)}, {M::RedBlackSor, 2 * picSorSweeps(grid)},
                                  {M::Multigrid, 1}, {M::Multigrid, 3}, {M::Multigrid, kPicMultigridCycles}});
    }
    const PeriodicGrid grid3(3, {64, 64, 64}, {1.0, 1.0, 1.0});
    measureSolvers(3, 64, {{M::Jacobi, 20}, {M::Jacobi, 200}, {M::RedBlackSor, 20},
                           {M::RedBlackSor, picSorSweeps(grid3)}, {M::RedBlackSor, 2 * picSorSweeps(grid3)},
                           {M::Multigrid, 1}, {M::Multigrid, 3}, {M::Multigrid, kPicMultigridCycles}});
    return 0;
}
