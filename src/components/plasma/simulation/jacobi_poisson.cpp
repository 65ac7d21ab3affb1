#include "components/plasma/simulation/jacobi_poisson.h"

#include "components/plasma/simulation/plasma_parameters.h"

#include <numeric>
#include <stdexcept>
#include <utility>

namespace aurorawall::components::plasma::simulation {

void jacobiSweeps(const PeriodicGrid& grid, const std::vector<double>& chargeDensity, std::vector<double>& potential,
                  int sweeps)
{
    if (chargeDensity.size() != grid.nodeCount() || potential.size() != grid.nodeCount())
        throw std::invalid_argument("jacobiSweeps: the fields are not on the grid");
    const double mean = std::accumulate(chargeDensity.begin(), chargeDensity.end(), 0.0) / double(chargeDensity.size());
    double diagonal = 0.0;
    for (int d = 0; d < grid.dimension; ++d)
        diagonal += 2.0 / (grid.spacing[d] * grid.spacing[d]);
    const int step[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    std::vector<double> next(potential.size());
    for (int sweep = 0; sweep < sweeps; ++sweep) {
        for (int k = 0; k < grid.cells[2]; ++k)
            for (int j = 0; j < grid.cells[1]; ++j)
                for (int i = 0; i < grid.cells[0]; ++i) {
                    double sum = (chargeDensity[grid.index(i, j, k)] - mean) / kVacuumPermittivity;
                    for (int d = 0; d < grid.dimension; ++d)
                        sum += (potential[grid.index(i + step[d][0], j + step[d][1], k + step[d][2])] +
                                potential[grid.index(i - step[d][0], j - step[d][1], k - step[d][2])]) /
                               (grid.spacing[d] * grid.spacing[d]);
                    next[grid.index(i, j, k)] = sum / diagonal;
                }
        std::swap(potential, next);
    }
}

} // namespace aurorawall::components::plasma::simulation
