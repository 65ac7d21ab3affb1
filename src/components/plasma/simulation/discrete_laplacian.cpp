#include "components/plasma/simulation/discrete_laplacian.h"

#include "components/plasma/simulation/plasma_parameters.h"

#include <cmath>
#include <numeric>

namespace aurorawall::components::plasma::simulation {

std::vector<double> laplacian(const PeriodicGrid& grid, const std::vector<double>& potential)
{
    std::vector<double> result(grid.nodeCount(), 0.0);
    for (int k = 0; k < grid.cells[2]; ++k)
        for (int j = 0; j < grid.cells[1]; ++j)
            for (int i = 0; i < grid.cells[0]; ++i) {
                const double centre = potential[grid.index(i, j, k)];
                const int step[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
                double sum = 0.0;
                for (int d = 0; d < grid.dimension; ++d) {
                    const double above = potential[grid.index(i + step[d][0], j + step[d][1], k + step[d][2])];
                    const double below = potential[grid.index(i - step[d][0], j - step[d][1], k - step[d][2])];
                    sum += (above - 2.0 * centre + below) / (grid.spacing[d] * grid.spacing[d]);
                }
                result[grid.index(i, j, k)] = sum;
            }
    return result;
}

double poissonResidual(const PeriodicGrid& grid, const std::vector<double>& chargeDensity,
                       const std::vector<double>& potential)
{
    const double mean = std::accumulate(chargeDensity.begin(), chargeDensity.end(), 0.0) / double(chargeDensity.size());
    const std::vector<double> lap = laplacian(grid, potential);
    double residual = 0.0, source = 0.0;
    for (std::size_t n = 0; n < lap.size(); ++n) {
        const double s = (chargeDensity[n] - mean) / kVacuumPermittivity;
        residual += (lap[n] + s) * (lap[n] + s);
        source += s * s;
    }
    return source > 0.0 ? std::sqrt(residual / source) : 0.0;
}

} // namespace aurorawall::components::plasma::simulation
