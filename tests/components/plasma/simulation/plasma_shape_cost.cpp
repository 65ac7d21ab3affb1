// Not a test: cloud-in-cell against the triangular-shaped cloud (docs/PLASMA.md, "Particle shape: CIC
// against TSC"). For a 1 eV thermal plasma on 64 cells (random start, ω_pΔt = 0.2) at Δx/λ_D = 0.5,
// 2, 8 and 4 to 128 particles per cell, each shape: the heating rate of the verify case (mean and
// standard error over seeds 1–8), the density noise (relative RMS of n/n₀ − 1 at the nodes) at the
// start and averaged over 10–200 /ω_p, and the time per step and per particle per step. Then the
// deposit, gather and whole step on a 3D grid, where TSC's 27 nodes against CIC's 8 cost most. Times
// are the process's CPU time (the machine is shared: its wall time counts the other processes too).
#include "components/plasma/simulation/electrostatic_pic.h"
#include "components/plasma/simulation/particle_loading.h"
#include "components/plasma/simulation/particle_mesh.h"
#include "components/plasma/simulation/plasma_parameters.h"
#include "components/plasma/simulation/verify_cases.h"

#include <cmath>
#include <cstdio>
#include <ctime>
#include <functional>

using namespace aurorawall::components::plasma::simulation;

namespace {

constexpr double kDensity = 1e12, kThermalSpeed = 4.19e5; // m⁻³, m/s (1 eV), as the verify cases
constexpr double kWpDt = 0.2;
constexpr int kCells = 64, kSeeds = 8;

const char* name(ParticleShape shape)
{
    return shape == ParticleShape::CloudInCell ? "cic" : "tsc";
}

double cpuSeconds()
{
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

double seconds(const std::function<void()>& work)
{
    const double start = cpuSeconds();
    work();
    return cpuSeconds() - start;
}

// The relative RMS of n/n₀ − 1 at the nodes, as the simulation's own deposit sees it.
double densityNoise(const PeriodicGrid& grid, const Particles& electrons, ParticleShape shape)
{
    double sum = 0.0;
    for (const double rho : depositChargeDensity(grid, electrons, shape)) {
        const double relative = rho / (kElementaryCharge * kDensity);
        sum += relative * relative;
    }
    return std::sqrt(sum / double(grid.nodeCount()));
}

double measuredHeatingRate(double dxOverDebye, std::uint64_t seed, ParticleShape shape, int perCell)
{
    for (const VerifyRow& row : verifyHeating(kWpDt, dxOverDebye, seed, cpuDevice(shape), perCell))
        if (row.parameter == "heating_rate_over_wp")
            return row.measured;
    return NAN;
}

void compareInOneDimension(double dxOverDebye, int perCell, ParticleShape shape)
{
    double sum = 0.0, sum2 = 0.0;
    for (std::uint64_t seed = 1; seed <= kSeeds; ++seed) {
        const double rate = measuredHeatingRate(dxOverDebye, seed, shape, perCell);
        sum += rate;
        sum2 += rate * rate;
    }
    const double mean = sum / kSeeds;
    const double standardError = std::sqrt((sum2 / kSeeds - mean * mean) / (kSeeds - 1));

    // The same run as the heating case's seed 1, timed step by step, the noise sampled every 10 steps.
    const double wp = plasmaFrequency(kDensity);
    const PeriodicGrid grid(1, {kCells, 1, 1}, {dxOverDebye * kThermalSpeed / wp, 1.0, 1.0});
    const Particles start = randomStart(grid, perCell * kCells, kDensity, kThermalSpeed, 1);
    const double startNoise = densityNoise(grid, start, shape);
    ElectrostaticPic pic(grid, start, glm::dvec3(0.0), kWpDt / wp, shape);
    const long steps = long(std::ceil(200.0 / kWpDt));
    double stepSeconds = 0.0, noise2 = 0.0;
    int samples = 0;
    for (long n = 0; n < steps; ++n) {
        stepSeconds += seconds([&] { pic.step(); });
        if (n * kWpDt >= 10.0 && n % 10 == 0) {
            const double noise = densityNoise(grid, pic.electrons(), shape);
            noise2 += noise * noise;
            ++samples;
        }
    }
    std::printf("%g,%d,%s,%.3e,%.1e,%.4f,%.4f,%.4f,%.1f\n", dxOverDebye, perCell, name(shape), mean, standardError,
                startNoise, std::sqrt(noise2 / samples), 1e3 * stepSeconds / steps,
                1e9 * stepSeconds / (double(steps) * perCell * kCells));
}

// 3D, 32³ cells, 8 particles per cell: deposit, gather and a whole step, ns per particle.
void costInThreeDimensions(ParticleShape shape)
{
    const double lambdaD = kThermalSpeed / plasmaFrequency(kDensity);
    const PeriodicGrid grid(3, {32, 32, 32}, {lambdaD, lambdaD, lambdaD});
    const int count = 8 * int(grid.nodeCount());
    const Particles electrons = randomStart(grid, count, kDensity, kThermalSpeed, 2);
    ElectrostaticPic pic(grid, electrons, glm::dvec3(0.0, 0.0, 5e-5), kWpDt / plasmaFrequency(kDensity), shape);
    constexpr int kRepeats = 3;
    const double deposit = seconds([&] {
        for (int r = 0; r < kRepeats; ++r) depositChargeDensity(grid, electrons, shape);
    });
    const double gather = seconds([&] {
        for (int r = 0; r < kRepeats; ++r) gatherField(grid, pic.nodeField(), electrons.position, shape);
    });
    const double step = seconds([&] {
        for (int r = 0; r < kRepeats; ++r) pic.step();
    });
    const double perParticle = 1e9 / (double(kRepeats) * count);
    std::printf("32^3,%d,%s,%.1f,%.1f,%.1f,%.1f\n", count, name(shape), deposit * perParticle, gather * perParticle,
                step * perParticle, 1e3 * step / kRepeats);
}

} // namespace

int main()
{
    std::printf("dx_over_debye,particles_per_cell,shape,heating_rate_over_wp,standard_error,noise_start,"
                "noise_thermal,ms_per_step,ns_per_particle_step\n");
    for (const double dxOverDebye : {0.5, 2.0, 8.0})
        for (const int perCell : {4, 8, 16, 32, 64, 128})
            for (const ParticleShape shape : {ParticleShape::CloudInCell, ParticleShape::TriangularShapedCloud})
                compareInOneDimension(dxOverDebye, perCell, shape);
    std::printf("grid,particles,shape,deposit_ns_per_particle,gather_ns_per_particle,step_ns_per_particle,ms_per_step\n");
    for (const ParticleShape shape : {ParticleShape::CloudInCell, ParticleShape::TriangularShapedCloud})
        costInThreeDimensions(shape);
}
