#pragma once
// Stable Fluids (Stam 1999, SIGGRAPH '99, 121–128) on a doubly periodic staggered (MAC) grid:
// semi-Lagrangian advection and a pressure projection solved by FFT or by multigrid. See docs/fluid.md.
#include "components/fluid_detail/simulation/fft_poisson.h"
#include "components/fluid_detail/simulation/multigrid.h"
#include "components/fluid_detail/simulation/periodic_field.h"

namespace aurorawall::components::fluid_detail::simulation {

// Cell (i, j) is [i hx, (i+1) hx] × [j hy, (j+1) hy] (km). Staggered velocity (km/s) on the
// cell faces (Harlow & Welch 1965): u(i, j) at (i hx, (j+½) hy), v(i, j) at ((i+½) hx, j hy);
// pressure, divergence and advected scalars at the cell centres ((i+½) hx, (j+½) hy).
struct MacVelocity {
    PeriodicField u;
    PeriodicField v;
};

// Discrete divergence at the cell centres: (∇·u)ᵢⱼ = (uᵢ₊₁ⱼ − uᵢⱼ)/hx + (vᵢⱼ₊₁ − vᵢⱼ)/hy, 1/s.
PeriodicField divergence(const MacVelocity& velocity);

// Semi-Lagrangian advection (Stam 1999, sec. 3.2, "method of characteristics"): each node takes
// the value found at the foot of its characteristic, q_new(x) = q(x − ∫u dt), traced back with
// the midpoint rule x_mid = x − (dt/2) u(x), x_back = x − dt u(x_mid), and read with the clamped
// Catmull–Rom interpolation (sampleCubicClamped), so the result stays within the old min/max.
// advectScalar: a cell-centred q; advectVelocity: u and v carried by the old velocity.
void advectScalar(PeriodicField& q, const MacVelocity& velocity, double dt);
void advectVelocity(MacVelocity& velocity, double dt);

// Pressure projection (Stam 1999, sec. 3.1, Helmholtz–Hodge decomposition): solve L φ = ∇·u,
// then u ← u − ∇φ with the face gradients (φᵢⱼ − φᵢ₋₁ⱼ)/hx and (φᵢⱼ − φᵢⱼ₋₁)/hy.
// On the MAC grid ∇·∇ is exactly the 5-point L, so the new divergence is the solver's residual:
// rounding for the FFT, the stopping tolerance for multigrid. φ (km²/s, the pressure times dt/ρ)
// is the result, and for multigrid also the initial guess.
void project(MacVelocity& velocity, PeriodicField& phi, FftPoisson& solver);
MultigridReport project(MacVelocity& velocity, PeriodicField& phi, const MultigridSettings& settings);

} // namespace aurorawall::components::fluid_detail::simulation
