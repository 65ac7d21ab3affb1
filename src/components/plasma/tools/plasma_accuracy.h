#pragma once
// `aurorawall plasma accuracy [--table NAME]`: the particle-in-cell plasma's error against its run
// time, as CSV tables with the cost measured on the spot (docs/PLASMA.md, "Error against run time"):
//   particles   the density noise of a thermal plasma against particles per cell, quiet and random
//   time-step   the relative energy error over a fixed physical time against ω_pΔt
//   solvers     the Poisson solvers (FFT, Jacobi 20 and 200 sweeps) against the FFT
//   heating     the numerical heating rate at Δx = 8 λ_D against particles per cell and ω_pΔt
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

namespace aurorawall::components::plasma::tools {

// The relative RMS of n/n₀ − 1 over the nodes at t = 0, against the closed form for a uniform random
// start deposited by CIC: each node sums the tensor-product hat weights W of N independent uniform
// particles, E[W] = 1/M and E[W²] = (2/3)^d/M on M cells (∫w² = 2/3 per axis), so
// var(n/n₀) = (2/3)^d/N_ppc − 1/N: the noise is 1/√(N_ppc (3/2)^d) up to the fixed total's −1/N.
// A quiet start (evenly spaced, 1D) puts the same charge on every node: closed form 0.
struct DensityNoiseRow {
    int dimension = 1;
    bool quiet = false;
    int particlesPerCell = 1;
    double noise = 0.0;
    double closedForm = 0.0;
    double msPerStep = 0.0; // one ElectrostaticPic step of the same plasma, ω_pΔt = 0.2 (median of 5)
};
DensityNoiseRow densityNoise(int dimension, bool quiet, int particlesPerCell);

// max over the run of |W_n − W_0|/W_0, W the total energy (StepEnergies), over a fixed physical time:
// "cold", a cold Langmuir wave (1D quiet start, 256 cells, 8 per cell, mode 1, 0.01 cell), 20 plasma
// periods; "thermal", a 1 eV plasma (1D random start, seed 1, Δx = λ_D, 64 cells, 64 per cell),
// 100/ω_p.
// The cold wave is the leapfrog's harmonic oscillator x_n = A cos(nφ), sin(φ/2) = ω_pΔt/2, from rest:
// with v_{n±1/2} = −Aω_p sin((n ± ½)φ) its energy ½ω_p²x_n² + ¼(v²_{n−1/2} + v²_{n+1/2}) is
// (A²ω_p²/4)(2 + (1 − cos φ) cos 2nφ), so max|W_n − W_0|/W_0 = 2(1 − cos φ)/(3 − cos φ)
// = 2(ω_pΔt)²/(4 + (ω_pΔt)²): second order in Δt.
struct EnergyErrorRow {
    std::string plasma;
    double wpDt = 0.0;
    long steps = 0;
    double relativeEnergyError = 0.0;
    std::optional<double> closedForm; // the cold wave's
    double msPerStep = 0.0;
};
EnergyErrorRow energyError(const std::string& plasma, double wpDt);

// One solve of ∇²φ = −ρ/ε₀ for the CIC density of a thermal plasma (random start, 2 per cell,
// Δx = λ_D): the residual ‖∇²φ + ρ̃/ε₀‖/‖ρ̃/ε₀‖ and the field's relative L2 error against the FFT's.
struct SolverRow {
    std::string grid;
    std::string solver;
    int sweeps = 0; // 0 for the FFT
    double residual = 0.0;
    double fieldError = 0.0;
    double msPerSolve = 0.0;
};
std::vector<SolverRow> solverTable(int dimension, int cellsPerAxis);

// The numerical heating of a 1 eV plasma (1D random start, 64 cells, Δx = 8 λ_D, no B), as the verify
// case heating measures it: the least-squares slope of kT_x/kT₀ = ⟨v_x²⟩/v_th² against ω_p t between
// 10 and 200 /ω_p (d(kT)/dt/(kT ω_p)); here with the particles per cell and the seed as parameters.
struct HeatingRow {
    int particlesPerCell = 64;
    double wpDt = 0.2;
    int seed = 1;
    double rate = 0.0;
    double msPerStep = 0.0;
};
HeatingRow heatingRate(int particlesPerCell, double wpDt, int seed);

// argv[0] is the action's name ("accuracy"). Prints the chosen table (or all, each after a blank
// line). Returns the exit status (cli/exit_status.h).
int runPlasmaAccuracyCommand(int argc, char** argv, std::ostream& out, std::ostream& err);

} // namespace aurorawall::components::plasma::tools
