#pragma once
// The charge density and the error measure of the GPU Poisson tests and of their cost table
// (plasma_gpu_test.cpp, plasma_gpu_cost.cpp): one definition, so that the table measures what the
// tests hold.
#include "physics/constants.h"
#include "components/plasma/simulation/periodic_grid.h"
#include "components/plasma/simulation/plasma_parameters.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

namespace aurorawall::test {

// A charge density (C/m³, ε₀ × V/m² with Δ = 1 m) of three Fourier modes, the longest wave
// included, plus uniform noise of a tenth of their amplitude (seed 7).
inline std::vector<double> modesAndNoise(const components::plasma::simulation::PeriodicGrid& grid)
{
    std::mt19937 random(7);
    std::uniform_real_distribution<double> noise(-0.1, 0.1);
    std::vector<double> rho(grid.nodeCount());
    for (int k = 0; k < grid.cells[2]; ++k)
        for (int j = 0; j < grid.cells[1]; ++j)
            for (int i = 0; i < grid.cells[0]; ++i) {
                const double x = 2.0 * aurorawall::physics::kPi * i / grid.cells[0], y = 2.0 * aurorawall::physics::kPi * j / grid.cells[1],
                             z = 2.0 * aurorawall::physics::kPi * k / grid.cells[2];
                rho[grid.index(i, j, k)] = components::plasma::simulation::kVacuumPermittivity * (std::cos(x) + 0.5 * std::sin(2 * x + 3 * y + z) +
                                                                          0.25 * std::cos(5 * x + y - 2 * z) + noise(random));
            }
    return rho;
}

// ‖a − mean(a) − b‖₂ / ‖b‖₂ (b has zero mean): a potential's error whatever constant it carries.
inline double relativePotentialError(const std::vector<double>& a, const std::vector<double>& b)
{
    double mean = 0.0;
    for (double v : a)
        mean += v;
    mean /= double(a.size());
    double difference = 0.0, norm = 0.0;
    for (std::size_t i = 0; i < b.size(); ++i) {
        difference += (a[i] - mean - b[i]) * (a[i] - mean - b[i]);
        norm += b[i] * b[i];
    }
    return std::sqrt(difference / norm);
}

// What float arithmetic allows a Poisson solver on the GPU, from the unit roundoff u = 2^-24 and
// the problem's condition, not from any device's output. A solver that has converged in float stops
// where each node's update is exact within its own rounding: c = 2d + 2 roundings (the 2d
// neighbours summed, the source added, the division), a backward error |δ_i| ≤ c·u·(λ_max·max|φ| +
// max|s|) in the equation Aφ = s (A = −∇², λ_max = Σ_d 4/Δ_d² its largest eigenvalue on an even grid;
// s = ρ/ε₀). That moves φ by A⁻¹δ, at most |δ|₂/λ_min with λ_min = min_d 4 sin²(π/n_d)/Δ_d², the
// longest wave's: relative to φ (RMS) the potential bound c·u·(λ_max·max|φ| + max|s|)/(λ_min·rms φ),
// about c·u·κ with κ = λ_max/λ_min. The residual of the float φ, relative to s (RMS), also carries
// the rounding of φ itself, one more u·λ_max·max|φ|: the residual bound
// (c + 1)·u·(λ_max·max|φ| + max|s|)/rms s. φ is the exact (double) solution.
struct FloatPoissonBounds {
    double potential, residual;
};

inline FloatPoissonBounds floatPoissonBounds(const components::plasma::simulation::PeriodicGrid& grid, const std::vector<double>& rho,
                                             const std::vector<double>& exactPotential)
{
    const double u = std::ldexp(1.0, -24), c = 2.0 * grid.dimension + 2.0;
    double largest = 0.0, smallest = HUGE_VAL;
    for (int d = 0; d < grid.dimension; ++d) {
        const double inverseSquare = 1.0 / (grid.spacing[d] * grid.spacing[d]);
        largest += 4.0 * inverseSquare;
        if (grid.cells[d] > 1)
            smallest = std::min(smallest, 4.0 * std::pow(std::sin(aurorawall::physics::kPi / grid.cells[d]), 2) * inverseSquare);
    }
    double mean = 0.0;
    for (double r : rho)
        mean += r;
    mean /= double(rho.size());
    double maxPotential = 0.0, squaredPotential = 0.0, maxSource = 0.0, squaredSource = 0.0;
    for (std::size_t i = 0; i < rho.size(); ++i) {
        const double s = (rho[i] - mean) / components::plasma::simulation::kVacuumPermittivity;
        maxPotential = std::max(maxPotential, std::abs(exactPotential[i]));
        squaredPotential += exactPotential[i] * exactPotential[i];
        maxSource = std::max(maxSource, std::abs(s));
        squaredSource += s * s;
    }
    const double n = double(rho.size());
    const double backward = u * (largest * maxPotential + maxSource);
    return {c * backward / (smallest * std::sqrt(squaredPotential / n)),
            (c + 1.0) * backward / std::sqrt(squaredSource / n)};
}

} // namespace aurorawall::test
