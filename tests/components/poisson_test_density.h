#pragma once
// The charge density and the error measure of the GPU Poisson tests and of their cost table
// (plasma_gpu_test.cpp, plasma_gpu_cost.cpp): one definition, so that the table measures what the
// tests hold.
#include "components/plasma/simulation/periodic_grid.h"
#include "components/plasma/simulation/plasma_parameters.h"

#include <cmath>
#include <random>
#include <vector>

namespace aurorawall::test {

// A charge density (C/m³, ε₀ × V/m² with Δ = 1 m) of three Fourier modes, the longest wave
// included, plus uniform noise of a tenth of their amplitude (seed 7).
inline std::vector<double> modesAndNoise(const plasma::PeriodicGrid& grid)
{
    std::mt19937 random(7);
    std::uniform_real_distribution<double> noise(-0.1, 0.1);
    std::vector<double> rho(grid.nodeCount());
    for (int k = 0; k < grid.cells[2]; ++k)
        for (int j = 0; j < grid.cells[1]; ++j)
            for (int i = 0; i < grid.cells[0]; ++i) {
                const double x = 2.0 * M_PI * i / grid.cells[0], y = 2.0 * M_PI * j / grid.cells[1],
                             z = 2.0 * M_PI * k / grid.cells[2];
                rho[grid.index(i, j, k)] = plasma::kVacuumPermittivity * (std::cos(x) + 0.5 * std::sin(2 * x + 3 * y + z) +
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

} // namespace aurorawall::test
