#pragma once
// The curtain-detail fluid simulation: a Kelvin–Helmholtz shear layer along the flux centre of an auroral curtain, in a strip periodic
// along and across the curtain, carrying the electron flux as a passive scalar. Its output, a
// few flux frames from smooth to turbulent, is wrapped along the curtain splines by the renderer.
// CPU, serial and deterministic: every rank computes the same bytes at start-up.
// See docs/fluid.md.
#include "components/fluid_detail/simulation/fft_poisson.h"
#include "components/fluid_detail/simulation/multigrid.h"
#include "components/fluid_detail/simulation/periodic_field.h"
#include "components/fluid_detail/simulation/stable_fluids.h"
#include "components/roles/flux_frames.h"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

namespace aurorawall::components::fluid_detail::simulation {

// How the pressure projection solves its Poisson problem (docs/fluid.md, "Pressure"): Fft is exact
// to rounding and the faster one at every grid measured; Multigrid stops at multigridTolerance.
enum class PressureSolver { Fft, Multigrid };

struct CurtainDetailSpec {
    int nx = 512;                      // cells along the curtain (power of two)
    int ny = 128;                      // cells across it (power of two)
    double stripLengthKm = 128.0;      // Lx, the period along the curtain
    double stripWidthKm = 32.0;        // Ly, the period across it
    double shearVelocity = 1.0;        // U, km/s: the flow is ±U on the two sides of the shear line
    double shearThicknessKm = 1.0;     // δ in u = U tanh(y'/δ)
    double fluxWidthKm = 1.0;          // σ, standard deviation of the initial Gaussian flux profile
    double perturbation = 0.02;        // ε, amplitude of the seed cross-stream velocity, units of U
    int frames = 16;                   // K flux frames; frame 0 is the initial condition
    double timeBetweenFramesS = 5.0;   // simulated seconds between frames
    int stepsPerFrame = 6;             // time steps between frames
    PressureSolver pressureSolver = PressureSolver::Fft;
    int multigridCycles = 20;          // V-cycles per projection at most (Multigrid only)
    double multigridTolerance = 1e-6;  // rms residual / rms divergence to stop at (Multigrid only)
    std::uint32_t seed = 1;            // picks the amplitudes and phases of the seed modes
};

// The flow state, stepped by simulateCurtainDetail and by the tests.
class CurtainFlow {
public:
    // The initial condition (docs/fluid.md, "Initial condition"), velocity projected once.
    // Throws std::invalid_argument for a spec outside its documented ranges.
    explicit CurtainFlow(const CurtainDetailSpec& spec);

    // One Stable Fluids step: flux advected by the current (divergence-free) velocity, then the
    // velocity advected by itself and projected. Returns the projection's multigrid report, or
    // nothing with the FFT solver.
    std::optional<MultigridReport> step(double dt);

    const PeriodicField& flux() const { return flux_; }
    const MacVelocity& velocity() const { return velocity_; }
    // ½ ∫ v² dA over the strip, km⁴/s²: the kinetic energy of the cross-stream velocity.
    double crossStreamEnergy() const;

private:
    std::optional<MultigridReport> project();

    std::optional<FftPoisson> fft_; // with PressureSolver::Fft: its plans, made once for the grid
    MultigridSettings settings_;
    MacVelocity velocity_;
    PeriodicField phi_;
    PeriodicField flux_;
};

// Runs the simulation: frame k is the flux at t = k·timeBetweenFramesS, stepsPerFrame steps apart.
roles::FluxFrames simulateCurtainDetail(const CurtainDetailSpec& spec);

} // namespace aurorawall::components::fluid_detail::simulation
