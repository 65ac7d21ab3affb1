#include "fluid/stable_fluids.h"

#include <utility>

namespace aurorawall::fluid {

void velocityAt(const MacVelocity& velocity, double x, double y, double& u, double& v)
{
    u = sampleBilinear(velocity.u, x / velocity.u.hx, y / velocity.u.hy - 0.5);
    v = sampleBilinear(velocity.v, x / velocity.v.hx - 0.5, y / velocity.v.hy);
}

PeriodicField divergence(const MacVelocity& velocity)
{
    const PeriodicField& u = velocity.u;
    const PeriodicField& v = velocity.v;
    PeriodicField d(u.nx, u.ny, u.hx, u.hy);
    for (int j = 0; j < u.ny; ++j)
        for (int i = 0; i < u.nx; ++i)
            d(i, j) = (u(i + 1, j) - u(i, j)) / u.hx + (v(i, j + 1) - v(i, j)) / u.hy;
    return d;
}

namespace {

// The semi-Lagrangian update of a field whose node (i, j) sits at ((i + ox) hx, (j + oy) hy).
PeriodicField advected(const PeriodicField& q, double ox, double oy, const MacVelocity& velocity, double dt)
{
    PeriodicField result(q.nx, q.ny, q.hx, q.hy);
    for (int j = 0; j < q.ny; ++j)
        for (int i = 0; i < q.nx; ++i) {
            const double x = (i + ox) * q.hx;
            const double y = (j + oy) * q.hy;
            double u = 0.0;
            double v = 0.0;
            velocityAt(velocity, x, y, u, v);
            velocityAt(velocity, x - 0.5 * dt * u, y - 0.5 * dt * v, u, v);
            result(i, j) = sampleCubicClamped(q, (x - dt * u) / q.hx - ox, (y - dt * v) / q.hy - oy);
        }
    return result;
}

} // namespace

void advectScalar(PeriodicField& q, const MacVelocity& velocity, double dt)
{
    q = advected(q, 0.5, 0.5, velocity, dt);
}

void advectVelocity(MacVelocity& velocity, double dt)
{
    MacVelocity next{advected(velocity.u, 0.0, 0.5, velocity, dt), advected(velocity.v, 0.5, 0.0, velocity, dt)};
    velocity = std::move(next);
}

MultigridReport project(MacVelocity& velocity, PeriodicField& phi, const MultigridSettings& settings)
{
    const MultigridReport report = solvePoisson(phi, divergence(velocity), settings);
    PeriodicField& u = velocity.u;
    PeriodicField& v = velocity.v;
    for (int j = 0; j < u.ny; ++j)
        for (int i = 0; i < u.nx; ++i) {
            u(i, j) -= (phi(i, j) - phi(i - 1, j)) / u.hx;
            v(i, j) -= (phi(i, j) - phi(i, j - 1)) / u.hy;
        }
    return report;
}

} // namespace aurorawall::fluid
