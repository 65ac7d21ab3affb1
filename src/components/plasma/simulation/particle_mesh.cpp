#include "components/plasma/simulation/particle_mesh.h"

#include "common/glsl.h"
#include "components/plasma/simulation/plasma_parameters.h"

#include <glm/geometric.hpp>

#include <cmath>
#include <numeric>

namespace aurorawall::components::plasma::simulation {
namespace {
namespace f64 {
AURORAWALL_GLSL_PRECISION(double)
#include "components/plasma/cloud_in_cell.glsl"
#include "components/plasma/triangular_shaped_cloud.glsl"
#include "components/plasma/electric_field.glsl"
} // namespace f64

// The particle's cell: its lower node and its fraction of the cell along each axis.
struct Cell {
    int lower[3];
    glm::dvec3 fraction;
};

Cell cellOf(const PeriodicGrid& grid, glm::dvec3 position)
{
    const glm::dvec3 g = position / glm::dvec3(grid.spacing[0], grid.spacing[1], grid.spacing[2]);
    const glm::dvec3 lower = glm::floor(g);
    return {{int(lower.x), int(lower.y), int(lower.z)}, f64::cicCellFraction(g)};
}

std::size_t cornerNode(const PeriodicGrid& grid, const Cell& cell, int corner)
{
    return grid.index(cell.lower[0] + (corner & 1), cell.lower[1] + ((corner >> 1) & 1),
                      cell.lower[2] + ((corner >> 2) & 1));
}

// The particle's nearest node and its offset from it along each axis (TSC).
struct NearestNode {
    int node[3];
    glm::dvec3 offset;
};

NearestNode nearestNodeOf(const PeriodicGrid& grid, glm::dvec3 position)
{
    const glm::dvec3 g = position / glm::dvec3(grid.spacing[0], grid.spacing[1], grid.spacing[2]);
    const glm::dvec3 nearest = f64::tscNearestNode(g);
    return {{int(nearest.x), int(nearest.y), int(nearest.z)}, f64::tscNodeOffset(g)};
}

// The grid index of TSC node `node` around the nearest node; no step along the axes beyond the
// grid's dimension.
std::size_t tscNode(const PeriodicGrid& grid, const NearestNode& nearest, int node)
{
    int at[3] = {nearest.node[0], nearest.node[1], nearest.node[2]};
    for (int d = 0; d < grid.dimension; ++d)
        at[d] += f64::tscNodeStep(node, d);
    return grid.index(at[0], at[1], at[2]);
}

int tscNodeCount(const PeriodicGrid& grid)
{
    return grid.dimension == 1 ? 3 : grid.dimension == 2 ? 9 : 27;
}

} // namespace

std::vector<double> depositChargeDensity(const PeriodicGrid& grid, const Particles& electrons, ParticleShape shape)
{
    std::vector<double> density(grid.nodeCount(), 0.0);
    const double charge = -kElementaryCharge * electrons.weight;
    const double volume = grid.cellVolume();
    if (shape == ParticleShape::CloudInCell) {
        const int corners = 1 << grid.dimension;
        for (const glm::dvec3& x : electrons.position) {
            const Cell cell = cellOf(grid, x);
            for (int corner = 0; corner < corners; ++corner)
                density[cornerNode(grid, cell, corner)] +=
                    f64::cicCornerChargeDensity(charge, volume, cell.fraction, corner, grid.dimension);
        }
    } else {
        const int nodes = tscNodeCount(grid);
        for (const glm::dvec3& x : electrons.position) {
            const NearestNode nearest = nearestNodeOf(grid, x);
            for (int node = 0; node < nodes; ++node)
                density[tscNode(grid, nearest, node)] +=
                    f64::tscNodeChargeDensity(charge, volume, nearest.offset, node, grid.dimension);
        }
    }
    const double mean = std::accumulate(density.begin(), density.end(), 0.0) / double(density.size());
    for (double& rho : density)
        rho -= mean;
    return density;
}

std::vector<double> depositChargeDensityAtCellCentres(const PeriodicGrid& grid, const Particles& electrons)
{
    Particles shifted = electrons;
    const glm::dvec3 box = grid.boxLength();
    for (glm::dvec3& x : shifted.position)
        for (int d = 0; d < grid.dimension; ++d) {
            x[d] -= 0.5 * grid.spacing[d];
            x[d] -= box[d] * std::floor(x[d] / box[d]);
        }
    return depositChargeDensity(grid, shifted);
}

std::vector<glm::dvec3> nodeElectricField(const PeriodicGrid& grid, const std::vector<double>& potential)
{
    std::vector<glm::dvec3> field(grid.nodeCount(), glm::dvec3(0.0));
    const int step[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    for (int k = 0; k < grid.cells[2]; ++k)
        for (int j = 0; j < grid.cells[1]; ++j)
            for (int i = 0; i < grid.cells[0]; ++i) {
                glm::dvec3& e = field[grid.index(i, j, k)];
                for (int d = 0; d < grid.dimension; ++d)
                    e[d] = f64::centralDifferenceField(
                        potential[grid.index(i - step[d][0], j - step[d][1], k - step[d][2])],
                        potential[grid.index(i + step[d][0], j + step[d][1], k + step[d][2])], grid.spacing[d]);
            }
    return field;
}

std::vector<glm::dvec3> gatherField(const PeriodicGrid& grid, const std::vector<glm::dvec3>& nodeField,
                                    const std::vector<glm::dvec3>& positions, ParticleShape shape)
{
    std::vector<glm::dvec3> field(positions.size(), glm::dvec3(0.0));
    if (shape == ParticleShape::CloudInCell) {
        const int corners = 1 << grid.dimension;
        for (std::size_t p = 0; p < positions.size(); ++p) {
            const Cell cell = cellOf(grid, positions[p]);
            for (int corner = 0; corner < corners; ++corner)
                field[p] += f64::cicCornerField(nodeField[cornerNode(grid, cell, corner)], cell.fraction, corner,
                                                grid.dimension);
        }
    } else {
        const int nodes = tscNodeCount(grid);
        for (std::size_t p = 0; p < positions.size(); ++p) {
            const NearestNode nearest = nearestNodeOf(grid, positions[p]);
            for (int node = 0; node < nodes; ++node)
                field[p] += f64::tscNodeField(nodeField[tscNode(grid, nearest, node)], nearest.offset, node,
                                              grid.dimension);
        }
    }
    return field;
}

} // namespace aurorawall::components::plasma::simulation
