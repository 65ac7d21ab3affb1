// Not a test: the cost of the plasma's CPU reference (docs/PLASMA.md, "Cost on the CPU"). Prints the Poisson
// solvers' residual and time per solve (Jacobi sweeps against the FFT) on a 64³ and a 256² grid, and
// the time per particle per step of push, deposit and gather on a 64³ grid.
#include "common/glsl.h"
#include "components/plasma/simulation/discrete_laplacian.h"
#include "components/plasma/simulation/electrostatic_pic.h"
#include "components/plasma/simulation/fft_poisson_solver.h"
#include "components/plasma/simulation/jacobi_poisson.h"
#include "components/plasma/simulation/particle_loading.h"
#include "components/plasma/simulation/particle_mesh.h"
#include "components/plasma/simulation/plasma_parameters.h"

#include <chrono>
#include <cstdio>
#include <functional>

// The push as the simulation runs it (a named namespace: not every function is used).
namespace aurorawall::plasma_cost::f64 {
AURORAWALL_GLSL_PRECISION(double)
#include "components/plasma/boris_push.glsl"
} // namespace aurorawall::plasma_cost::f64

using namespace aurorawall::components::plasma::simulation;
namespace f64 = aurorawall::plasma_cost::f64;

namespace {

constexpr double kDensity = 1e12, kThermalSpeed = 4.19e5; // m⁻³, m/s (1 eV)

double seconds(const std::function<void()>& work, int repeats)
{
    const auto start = std::chrono::steady_clock::now();
    for (int r = 0; r < repeats; ++r) work();
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() / repeats;
}

// A thermal plasma's charge density on the grid (Δx = λ_D), with about 2 particles per cell.
void compareSolvers(const char* name, const PeriodicGrid& grid)
{
    const Particles electrons = randomStart(grid, int(2 * grid.nodeCount()), kDensity, kThermalSpeed, 1);
    const std::vector<double> rho = depositChargeDensity(grid, electrons);
    const FftPoissonSolver fft(grid);
    std::vector<double> phi;
    const double fftSeconds = seconds([&] { phi = fft.solve(rho); }, 10);
    std::printf("%s,fft,1,%.3g,%.3f\n", name, poissonResidual(grid, rho, phi), 1e3 * fftSeconds);
    std::vector<double> jacobi(grid.nodeCount(), 0.0);
    int done = 0;
    for (const int sweeps : {20, 200, 2000}) {
        const double s = seconds([&] { jacobiSweeps(grid, rho, jacobi, sweeps - done); }, 1);
        std::printf("%s,jacobi,%d,%.3g,%.3f\n", name, sweeps, poissonResidual(grid, rho, jacobi),
                    1e3 * s / (sweeps - done) * sweeps);
        done = sweeps;
    }
}

} // namespace

int main()
{
    const double lambdaD = kThermalSpeed / plasmaFrequency(kDensity);
    std::printf("grid,solver,sweeps,residual,ms_per_solve\n");
    compareSolvers("64^3", PeriodicGrid(3, {64, 64, 64}, {lambdaD, lambdaD, lambdaD}));
    compareSolvers("256^2", PeriodicGrid(2, {256, 256, 1}, {lambdaD, lambdaD, 1.0}));

    const PeriodicGrid grid(3, {64, 64, 64}, {lambdaD, lambdaD, lambdaD});
    const int count = 2 * int(grid.nodeCount());
    Particles electrons = randomStart(grid, count, kDensity, kThermalSpeed, 2);
    const std::vector<double> rho = depositChargeDensity(grid, electrons);
    const std::vector<glm::dvec3> field = nodeElectricField(grid, FftPoissonSolver(grid).solve(rho));
    const double deposit = seconds([&] { depositChargeDensity(grid, electrons); }, 5);
    const double gather = seconds([&] { gatherField(grid, field, electrons.position); }, 5);
    const std::vector<glm::dvec3> atParticles = gatherField(grid, field, electrons.position);
    const glm::dvec3 box = grid.boxLength(), b(0.0, 0.0, 5e-5);
    const double dt = 0.2 / plasmaFrequency(kDensity), qm = -kElementaryCharge / kElectronMass;
    const double push = seconds([&] {
        for (int p = 0; p < count; ++p) {
            electrons.velocity[p] = f64::borisVelocity(electrons.velocity[p], atParticles[p], b, qm, dt);
            electrons.position[p] = f64::leapfrogPosition(electrons.position[p], electrons.velocity[p], dt, box);
        }
    }, 5);
    ElectrostaticPic pic(grid, electrons, glm::dvec3(0.0, 0.0, 5e-5), 0.2 / plasmaFrequency(kDensity));
    const double step = seconds([&] { pic.step(); }, 5);
    std::printf("\nparticles,cells,push_ns,deposit_ns,gather_ns,whole_step_ns (per particle)\n");
    std::printf("%d,64^3,%.1f,%.1f,%.1f,%.1f\n", count, 1e9 * push / count, 1e9 * deposit / count, 1e9 * gather / count,
                1e9 * step / count);
    return 0;
}
