#include "components/plasma/simulation/particle_loading.h"

#include "physics/constants.h"

#include <boost/math/special_functions/erf.hpp>
#include <glm/common.hpp>

#include <cmath>
#include <random>
#include <stdexcept>

namespace aurorawall::components::plasma::simulation {
namespace {

double weightFor(const PeriodicGrid& grid, int count, double electronDensity)
{
    if (count < 1 || !(electronDensity > 0.0))
        throw std::invalid_argument("particle loading: needs at least one particle and a density > 0");
    const glm::dvec3 box = grid.boxLength();
    return electronDensity * box.x * box.y * box.z / count;
}

glm::dvec3 evenlySpaced(const PeriodicGrid& grid, int i, int count, Perturbation perturbation)
{
    const glm::dvec3 box = grid.boxLength();
    const double x = (i + 0.5) * box.x / count;
    const double displaced = x + perturbation.amplitude * std::sin(2.0 * physics::kPi * perturbation.mode * x / box.x);
    return {displaced - box.x * std::floor(displaced / box.x), 0.5 * box.y, 0.5 * box.z};
}

} // namespace

Particles quietStart(const PeriodicGrid& grid, int count, double electronDensity, Perturbation perturbation,
                     glm::dvec3 drift)
{
    Particles p;
    p.weight = weightFor(grid, count, electronDensity);
    for (int i = 0; i < count; ++i) {
        p.position.push_back(evenlySpaced(grid, i, count, perturbation));
        p.velocity.push_back(drift);
    }
    return p;
}

Particles diagonalWaveLattice(const PeriodicGrid& grid, int perCellPerAxis, double electronDensity,
                              Perturbation perturbation)
{
    if (grid.dimension < 2 || perCellPerAxis < 1)
        throw std::invalid_argument("diagonalWaveLattice: needs a 2D or 3D grid and at least one particle per axis");
    const bool solid = grid.dimension == 3;
    const int nx = grid.cells[0] * perCellPerAxis, ny = grid.cells[1] * perCellPerAxis;
    const int nz = solid ? grid.cells[2] * perCellPerAxis : 1;
    const glm::dvec3 box = grid.boxLength();
    const double component = 1.0 / std::sqrt(double(grid.dimension));
    const glm::dvec3 diagonal(component, component, solid ? component : 0.0);
    Particles p;
    p.weight = weightFor(grid, nx * ny * nz, electronDensity);
    for (int k = 0; k < nz; ++k)
        for (int j = 0; j < ny; ++j)
            for (int i = 0; i < nx; ++i) {
                const glm::dvec3 x((i + 0.5) * box.x / nx, (j + 0.5) * box.y / ny, (k + 0.5) * box.z / nz);
                const double phase =
                    2.0 * physics::kPi * perturbation.mode * (x.x / box.x + x.y / box.y + (solid ? x.z / box.z : 0.0));
                glm::dvec3 displaced = x + perturbation.amplitude * std::sin(phase) * diagonal;
                displaced -= box * glm::floor(displaced / box);
                p.position.push_back(displaced);
                p.velocity.push_back(glm::dvec3(0.0));
            }
    return p;
}

Particles quietMaxwellian(const PeriodicGrid& grid, int count, double electronDensity, Perturbation perturbation,
                          double thermalSpeed)
{
    if (count < 1 || (count & (count - 1)) != 0)
        throw std::invalid_argument("quietMaxwellian: the particle count must be a power of two");
    int bits = 0;
    while ((1 << bits) < count) ++bits;
    Particles p = quietStart(grid, count, electronDensity, perturbation, glm::dvec3(0.0));
    for (int i = 0; i < count; ++i) {
        int reversed = 0;
        for (int b = 0; b < bits; ++b)
            reversed |= ((i >> b) & 1) << (bits - 1 - b);
        const double u = (reversed + 0.5) / count;
        p.velocity[i].x = thermalSpeed * std::sqrt(2.0) * boost::math::erf_inv(2.0 * u - 1.0);
    }
    return p;
}

Particles randomStart(const PeriodicGrid& grid, int count, double electronDensity, double thermalSpeed,
                      std::uint64_t seed)
{
    Particles p;
    p.weight = weightFor(grid, count, electronDensity);
    std::mt19937_64 engine(seed);
    const auto uniform = [&engine] { return double(engine() >> 11) * 0x1.0p-53; }; // [0, 1)
    const auto normal = [&uniform] {
        const double u1 = 1.0 - uniform(); // (0, 1]: the logarithm stays finite
        return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * physics::kPi * uniform());
    };
    const glm::dvec3 box = grid.boxLength();
    for (int i = 0; i < count; ++i) {
        glm::dvec3 x(0.5 * box);
        for (int d = 0; d < grid.dimension; ++d)
            x[d] = uniform() * box[d];
        p.position.push_back(x);
        const double vx = normal(), vy = normal(), vz = normal();
        p.velocity.push_back(thermalSpeed * glm::dvec3(vx, vy, vz));
    }
    return p;
}

} // namespace aurorawall::components::plasma::simulation
