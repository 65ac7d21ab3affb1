#pragma once
// Electrostatic particle-in-cell electrons on a neutralising ion background in a static uniform
// magnetic field, on a periodic grid, in SI units (Birdsall & Langdon 1991, ch. 2–4 and 8).
// One step from time n to n+1 (positions x at whole steps, velocities v at half steps):
//   ρ(x_n) by the particle shape (CIC or TSC), minus its mean → φ by FFT → E = −∇φ at the nodes → E at the particles
//   → v_{n+1/2} by the Boris push → x_{n+1} = x_n + v_{n+1/2} Δt, wrapped into the box.
// Stable for ω_p Δt < 2 (the leapfrog's limit), any ω_c Δt.
#include "components/plasma/simulation/fft_poisson_solver.h"
#include "components/plasma/simulation/particle_mesh.h"
#include "components/plasma/simulation/particles.h"
#include "components/plasma/simulation/periodic_grid.h"

#include <glm/vec3.hpp>

#include <vector>

namespace aurorawall::components::plasma::simulation {

// The energies (J; in 1D and 2D per m² or per m of the unresolved axes) at one whole step.
struct StepEnergies {
    double field = 0.0;   // ½ Σ ρ φ ΔV
    double kinetic = 0.0; // Σ ½ m (|v_{n−1/2}|² + |v_{n+1/2}|²)/2 (Birdsall & Langdon 1991, §3-7)
    double total() const { return field + kinetic; }
};

class ElectrostaticPic {
public:
    // electrons: positions and velocities at time 0; the velocities are taken back half a step
    // (a Boris push of −Δt/2 in the initial field) to start the leapfrog. magneticField (T), dt (s).
    // shape: the weights of both the deposit and the gather.
    ElectrostaticPic(const PeriodicGrid& grid, Particles electrons, glm::dvec3 magneticField, double dt,
                     ParticleShape shape = ParticleShape::CloudInCell);

    // Advances from step n to n+1 and returns the energies at step n.
    StepEnergies step();

    long stepCount() const { return steps_; }
    const PeriodicGrid& grid() const { return grid_; }
    ParticleShape shape() const { return shape_; }
    const Particles& electrons() const { return electrons_; }
    // The fields at the current step (V and V/m at the nodes).
    const std::vector<double>& potential() const { return potential_; }
    const std::vector<glm::dvec3>& nodeField() const { return nodeField_; }

private:
    void solveFields();

    PeriodicGrid grid_;
    FftPoissonSolver poisson_;
    Particles electrons_;
    glm::dvec3 magneticField_;
    double dt_;
    ParticleShape shape_;
    long steps_ = 0;
    std::vector<double> chargeDensity_;
    std::vector<double> potential_;
    std::vector<glm::dvec3> nodeField_;
};

} // namespace aurorawall::components::plasma::simulation
