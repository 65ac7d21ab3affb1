#include "components/plasma/simulation/periodic_grid.h"

#include <stdexcept>

namespace aurorawall::components::plasma::simulation {
namespace {

int wrap(int i, int n)
{
    const int r = i % n;
    return r < 0 ? r + n : r;
}

} // namespace

PeriodicGrid::PeriodicGrid(int dimension_, std::array<int, 3> cells_, std::array<double, 3> spacing_)
    : dimension(dimension_), cells(cells_), spacing(spacing_)
{
    if (dimension < 1 || dimension > 3)
        throw std::invalid_argument("PeriodicGrid: dimension must be 1, 2 or 3");
    for (int d = 0; d < 3; ++d) {
        if (d >= dimension) {
            cells[d] = 1;
            spacing[d] = 1.0;
        } else if (cells[d] < 1 || !(spacing[d] > 0.0)) {
            throw std::invalid_argument("PeriodicGrid: every axis needs at least one cell and a spacing > 0");
        }
    }
}

std::size_t PeriodicGrid::index(int i, int j, int k) const
{
    return std::size_t(wrap(i, cells[0])) +
           std::size_t(cells[0]) * (std::size_t(wrap(j, cells[1])) + std::size_t(cells[1]) * std::size_t(wrap(k, cells[2])));
}

glm::dvec3 PeriodicGrid::boxLength() const
{
    return {cells[0] * spacing[0], cells[1] * spacing[1], cells[2] * spacing[2]};
}

} // namespace aurorawall::components::plasma::simulation
