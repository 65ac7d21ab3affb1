#include "components/fluid_detail/simulation/stable_fluids.h"

#include <utility>

namespace aurorawall::components::fluid_detail::simulation {

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

// The velocity in cells per second, (u/hx, v/hy), at (X, Y) = (x/hx, y/hy), each component
// interpolated bilinearly from its faces (u-face (i, j) at X = i, Y = j + ½; v-face at
// X = i + ½, Y = j).
void cellVelocityAt(const MacVelocity& velocity, double inverseHx, double inverseHy, double X, double Y, double& cu,
                    double& cv)
{
    cu = sampleBilinear(velocity.u, X, Y - 0.5) * inverseHx;
    cv = sampleBilinear(velocity.v, X - 0.5, Y) * inverseHy;
}

// The semi-Lagrangian update of a field whose node (i, j) sits at ((i + ox) hx, (j + oy) hy),
// traced in cell units (X, Y) = (x/hx, y/hy).
PeriodicField advected(const PeriodicField& q, double ox, double oy, const MacVelocity& velocity, double dt)
{
    PeriodicField result(q.nx, q.ny, q.hx, q.hy);
    const double inverseHx = 1.0 / q.hx;
    const double inverseHy = 1.0 / q.hy;
    for (int j = 0; j < q.ny; ++j)
        for (int i = 0; i < q.nx; ++i) {
            const double X = i + ox;
            const double Y = j + oy;
            double cu = 0.0;
            double cv = 0.0;
            cellVelocityAt(velocity, inverseHx, inverseHy, X, Y, cu, cv);
            cellVelocityAt(velocity, inverseHx, inverseHy, X - 0.5 * dt * cu, Y - 0.5 * dt * cv, cu, cv);
            result(i, j) = sampleCubicClamped(q, X - dt * cu - ox, Y - dt * cv - oy);
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

namespace {

// u ← u − ∇φ on the faces.
void subtractGradient(MacVelocity& velocity, const PeriodicField& phi)
{
    PeriodicField& u = velocity.u;
    PeriodicField& v = velocity.v;
    for (int j = 0; j < u.ny; ++j)
        for (int i = 0; i < u.nx; ++i) {
            u(i, j) -= (phi(i, j) - phi(i - 1, j)) / u.hx;
            v(i, j) -= (phi(i, j) - phi(i, j - 1)) / u.hy;
        }
}

} // namespace

void project(MacVelocity& velocity, PeriodicField& phi, FftPoisson& solver)
{
    solver.solve(phi, divergence(velocity));
    subtractGradient(velocity, phi);
}

MultigridReport project(MacVelocity& velocity, PeriodicField& phi, const MultigridSettings& settings)
{
    const MultigridReport report = solvePoisson(phi, divergence(velocity), settings);
    subtractGradient(velocity, phi);
    return report;
}

} // namespace aurorawall::components::fluid_detail::simulation
