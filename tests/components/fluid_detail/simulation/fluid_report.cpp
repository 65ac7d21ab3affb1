// The cost and the diagnostics of docs/fluid.md and bench/results/fluid (benchmark; not run by ctest), one core:
// run time of simulateCurtainDetail for the default and the two quality knobs with each pressure
// solver, how far the two runs' flux frames drift apart, and one projection side by side (error
// against a multigrid solve to a residual of 1e-12, divergence left, milliseconds per projection).
#include "components/fluid_detail/simulation/curtain_detail.h"
#include "flow_metrics.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <functional>

using namespace aurorawall::components::fluid_detail::simulation;
using aurorawall::components::roles::FluxFrames;

namespace {

struct Knob {
    const char* name;
    int nx, ny, stepsPerFrame;
};

CurtainDetailSpec specOf(const Knob& knob, PressureSolver solver)
{
    CurtainDetailSpec spec;
    spec.nx = knob.nx;
    spec.ny = knob.ny;
    spec.stepsPerFrame = knob.stepsPerFrame;
    spec.pressureSolver = solver;
    return spec;
}

double seconds(std::chrono::steady_clock::time_point since)
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - since).count();
}

// rms(a − b) / rms(b) over frame k.
double frameDifference(const FluxFrames& a, const FluxFrames& b, int k)
{
    double difference = 0.0, reference = 0.0;
    for (int iy = 0; iy < a.ny; ++iy)
        for (int ix = 0; ix < a.nx; ++ix) {
            const double d = double(a.at(k, ix, iy)) - double(b.at(k, ix, iy));
            difference += d * d;
            reference += double(b.at(k, ix, iy)) * double(b.at(k, ix, iy));
        }
    return std::sqrt(difference / reference);
}

double maxVelocityDifference(const MacVelocity& a, const MacVelocity& b)
{
    double difference = 0.0, scale = 0.0;
    for (std::size_t k = 0; k < a.u.values.size(); ++k) {
        difference = std::max({difference, std::abs(a.u.values[k] - b.u.values[k]), std::abs(a.v.values[k] - b.v.values[k])});
        scale = std::max({scale, std::abs(b.u.values[k]), std::abs(b.v.values[k])});
    }
    return difference / scale;
}

// One projection of the velocity the default run's frame-8 step projects (billows rolling up),
// warm-started, like the simulation, from the previous step's pressure; ms from `repeats` calls.
void compareProjections(const Knob& knob)
{
    const CurtainDetailSpec spec = specOf(knob, PressureSolver::Fft);
    const double dt = spec.timeBetweenFramesS / spec.stepsPerFrame;
    CurtainFlow flow(spec);
    for (int n = 0; n < 8 * spec.stepsPerFrame - 1; ++n)
        flow.step(dt);
    const double hx = spec.stripLengthKm / spec.nx, hy = spec.stripWidthKm / spec.ny;
    FftPoisson fft(spec.nx, spec.ny, hx, hy);
    MacVelocity previous = flow.velocity();
    advectVelocity(previous, dt);
    PeriodicField previousPhi(spec.nx, spec.ny, hx, hy);
    project(previous, previousPhi, fft);
    MacVelocity unprojected = previous;
    advectVelocity(unprojected, dt);

    MacVelocity reference = unprojected;
    PeriodicField referencePhi = previousPhi;
    const MultigridReport converged = project(reference, referencePhi, MultigridSettings{60, 1e-12, 2, 2});
    std::printf("%s %dx%d, one projection (reference: multigrid to 1e-12, %d V-cycles):\n", knob.name, spec.nx, spec.ny,
                converged.cycles());

    const int repeats = std::max(8, (1 << 22) / (spec.nx * spec.ny));
    const auto measure = [&](const char* name, const std::function<int(MacVelocity&, PeriodicField&)>& solve,
                             const PeriodicField& guess) {
        MacVelocity velocity;
        double total = 0.0;
        int cycles = 0;
        for (int r = 0; r < repeats; ++r) {
            velocity = unprojected;
            PeriodicField phi = guess;
            const auto start = std::chrono::steady_clock::now();
            cycles = solve(velocity, phi);
            total += seconds(start);
        }
        std::printf("  %-26s error %.2e  div/|grad u| %.2e  %6.2f ms", name, maxVelocityDifference(velocity, reference),
                    divergenceRms(velocity) / gradientRms(velocity), 1e3 * total / repeats);
        std::printf(cycles < 0 ? "\n" : "  V-cycles %d\n", cycles);
    };
    const PeriodicField zero(spec.nx, spec.ny, hx, hy);
    measure("FFT", [&](MacVelocity& v, PeriodicField& phi) { project(v, phi, fft); return -1; }, zero);
    measure("multigrid 1e-6, warm start",
            [&](MacVelocity& v, PeriodicField& phi) { return project(v, phi, MultigridSettings{}).cycles(); }, previousPhi);
    measure("multigrid 1e-6, cold start",
            [&](MacVelocity& v, PeriodicField& phi) { return project(v, phi, MultigridSettings{}).cycles(); }, zero);
}

} // namespace

int main()
{
    const Knob knobs[] = {{"low", 256, 64, 3}, {"default", 512, 128, 6}, {"high", 1024, 256, 12}};
    for (const Knob& knob : knobs) {
        FluxFrames frames[2];
        for (PressureSolver solver : {PressureSolver::Fft, PressureSolver::Multigrid}) {
            const CurtainDetailSpec spec = specOf(knob, solver);
            const std::clock_t cpu0 = std::clock();
            const auto wall0 = std::chrono::steady_clock::now();
            FluxFrames& f = frames[solver == PressureSolver::Fft ? 0 : 1];
            f = simulateCurtainDetail(spec);
            const double wall = seconds(wall0);
            const double cpu = double(std::clock() - cpu0) / CLOCKS_PER_SEC;
            std::printf("%-7s %4dx%-3d %2d steps/frame %3d steps, %-9s: %.3f s wall, %.3f s cpu, %zu floats\n", knob.name,
                        knob.nx, knob.ny, knob.stepsPerFrame, knob.stepsPerFrame * (spec.frames - 1),
                        solver == PressureSolver::Fft ? "FFT" : "multigrid", wall, cpu, f.flux.size());
        }
        std::printf("  rms(F_multigrid - F_fft) / rms F at frames 1, 4, 8, 12, 15:");
        for (int k : {1, 4, 8, 12, 15})
            std::printf(" %.1e", frameDifference(frames[1], frames[0], k));
        std::printf("\n");
    }

    CurtainDetailSpec spec;
    spec.pressureSolver = PressureSolver::Multigrid;
    CurtainFlow flow(spec);
    int cycles = 0, steps = 0, worst = 0;
    for (int k = 1; k < spec.frames; ++k)
        for (int n = 0; n < spec.stepsPerFrame; ++n) {
            const int c = flow.step(spec.timeBetweenFramesS / spec.stepsPerFrame)->cycles();
            cycles += c;
            worst = std::max(worst, c);
            ++steps;
        }
    std::printf("default with multigrid: %.2f V-cycles per projection on average, %d at most\n", double(cycles) / steps, worst);

    for (const Knob& knob : knobs)
        compareProjections(knob);
}
