#pragma once
// Diagnostics the fluid tests share.
#include "components/fluid_detail/simulation/stable_fluids.h"

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace aurorawall::components::fluid_detail::simulation {

// rms over the cells of |∇u| = sqrt(u_x² + u_y² + v_x² + v_y²), forward differences.
inline double gradientRms(const MacVelocity& velocity)
{
    const PeriodicField& u = velocity.u;
    const PeriodicField& v = velocity.v;
    double sum = 0.0;
    for (int j = 0; j < u.ny; ++j)
        for (int i = 0; i < u.nx; ++i) {
            const double ux = (u(i + 1, j) - u(i, j)) / u.hx, uy = (u(i, j + 1) - u(i, j)) / u.hy;
            const double vx = (v(i + 1, j) - v(i, j)) / u.hx, vy = (v(i, j + 1) - v(i, j)) / u.hy;
            sum += ux * ux + uy * uy + vx * vx + vy * vy;
        }
    return std::sqrt(sum / double(u.nx * u.ny));
}

// The largest |a − b| over the cells of two fields of one grid.
inline double maxAbsDifference(const PeriodicField& a, const PeriodicField& b)
{
    double e = 0.0;
    for (std::size_t k = 0; k < a.values.size(); ++k)
        e = std::max(e, std::abs(a.values[k] - b.values[k]));
    return e;
}

// The largest difference of either component over the faces of two velocities of one grid.
inline double maxAbsDifference(const MacVelocity& a, const MacVelocity& b)
{
    return std::max(maxAbsDifference(a.u, b.u), maxAbsDifference(a.v, b.v));
}

// rms of the discrete divergence over the cells.
inline double divergenceRms(const MacVelocity& velocity)
{
    return divergence(velocity).rms();
}

} // namespace aurorawall::components::fluid_detail::simulation
