#pragma once
// The electrostatic particle-in-cell step of ElectrostaticPic on the GPU (GLSL compute shaders,
// shaders/components/plasma/pic_step.comp, in float), deterministic: the same particles give the
// same bits in every run and every context. Needs a current GL 4.5 context.
//
// Each step: gather and push on the GPU; the deposit on the GPU in fixed point (integer atomics);
// the potential solved by the chosen GpuPicSolver (below); E = −∇φ at the nodes on the GPU.
#include "components/plasma/gpu/gpu_poisson.h"
#include "components/plasma/simulation/fft_poisson_solver.h"
#include "components/plasma/simulation/particles.h"
#include "components/plasma/simulation/periodic_grid.h"

#include <glm/vec3.hpp>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace aurorawall::components::plasma::gpu {

// The fixed-point deposit's resolution: a particle's CIC weights are multiples of 2^-bits and add to
// exactly 1. The largest possible node sum (every particle on one node) must fit a 32-bit signed
// integer: count · (2^bits + 2^dimension) < 2^31 (the last corner's share can dip below 0 by up to
// half a quantum per other corner). bits: the largest such value, at most 20 (float weights carry 24
// bits); std::invalid_argument naming both counts if even 8 bits would overflow (more than 8323580
// particles in 1D, 8134407 in 3D).
int depositQuantumBits(std::size_t particleCount, int dimension);

// The step's Poisson solve.
//   FftCpu: the node sums read back, the ion background subtracted in integers (Σρ = 0 exactly), φ
//     solved exactly by FFT in double on the CPU and uploaded as float: one read-back and one upload
//     per step.
//   Jacobi: kPicJacobiSweeps Jacobi sweeps on the GPU (GpuPoisson), from the previous step's φ.
//   RedBlackSor: picSorSweeps(grid) red-black SOR sweeps on the GPU, from the previous step's φ.
//   Multigrid: kPicMultigridCycles V-cycles on the GPU, from the previous step's φ (needs even cell
//     counts, as RedBlackSor).
// The GPU solvers take the source from the node sums on the GPU: nothing is read back.
enum class GpuPicSolver { FftCpu, Jacobi, RedBlackSor, Multigrid };

inline constexpr int kPicJacobiSweeps = 20;
// From φ = 0 six V-cycles reach float round-off on 64² and 32³ (docs/PLASMA.md).
inline constexpr int kPicMultigridCycles = 6;
// The red-black SOR sweeps that shrink the slowest error by 10^-6 at the rate ω − 1 per sweep.
int picSorSweeps(const simulation::PeriodicGrid& grid);

// The solver of a live simulation on this grid and renderer (GL_RENDERER): on a GPU, Multigrid,
// exact to float (its error after kPicMultigridCycles from the previous step's φ is float rounding,
// docs/PLASMA.md) with nothing read back, where every axis of the dimension has an even cell count;
// FftCpu otherwise, and on Mesa's CPU renderers, where the multigrid's many small dispatches cost
// more than the FFT in double (the live strip of tests/components/plasma/gpu/plasma_gpu_test.cpp: 5-20 times).
GpuPicSolver preferredGpuPicSolver(const simulation::PeriodicGrid& grid, const std::string& rendererName);

// The wall-clock time (ms) of each phase of one step, each waited for with glFinish.
struct StepTimes {
    double pushMs = 0.0;    // gather and Boris push, all particles
    double depositMs = 0.0; // fixed-point CIC deposit, all particles
    double solveMs = 0.0;   // the Poisson solve (FftCpu: read-back, FFT in double, upload of φ)
    double fieldMs = 0.0;   // E = −∇φ at the nodes
};

class GpuPic {
public:
    // As ElectrostaticPic: electrons at time 0, velocities taken back half a step in the initial
    // field. externalField (V/m) is a uniform field added to the particles' own; magneticField (T),
    // dt (s). shaderDir holds components/plasma/. A particle weight of 0 makes test particles (no
    // charge: the self-consistent field stays 0). std::invalid_argument for RedBlackSor on a grid
    // with an odd cell count. Before anything is made on the GPU: std::invalid_argument for more
    // particles than the fixed-point deposit can sum (depositQuantumBits), std::length_error for more
    // particles or grid nodes than one dispatch (GL_MAX_COMPUTE_WORK_GROUP_COUNT) or one storage
    // block (GL_MAX_SHADER_STORAGE_BLOCK_SIZE) holds; each message names the limit and the numbers.
    GpuPic(const simulation::PeriodicGrid& grid, const simulation::Particles& electrons, glm::dvec3 magneticField, double dt,
           const std::string& shaderDir, glm::dvec3 externalField = glm::dvec3(0.0),
           GpuPicSolver solver = GpuPicSolver::FftCpu);
    ~GpuPic();
    GpuPic(const GpuPic&) = delete;
    GpuPic& operator=(const GpuPic&) = delete;

    // Advances from step n to n + 1.
    void step();
    // The same step, timed phase by phase (slower: it waits for the GPU after each).
    StepTimes timedStep();

    long stepCount() const { return steps_; }
    const simulation::PeriodicGrid& grid() const { return grid_; }
    int quantumBits() const { return quantumBits_; }
    GpuPicSolver solver() const { return solver_; }
    // The charge density (C/m³) at the nodes of the current step, from the fixed-point sums (read
    // back from the GPU once per step, when asked or for FftCpu).
    const std::vector<double>& chargeDensity() const;
    // Read back from the GPU: positions (m), velocities (m/s, half a step behind), the field at the
    // nodes (V/m), all of the current step.
    std::vector<glm::dvec3> positions() const;
    std::vector<glm::dvec3> velocities() const;
    std::vector<glm::dvec3> nodeField() const;
    // The potential at the nodes (V) of the current step, read back from the GPU (float).
    std::vector<double> potential() const;

private:
    struct Programs;
    // `grid`, once the grid and the particle count fit the deposit and the current context's limits.
    static const simulation::PeriodicGrid& checkedAgainstGpuLimits(const simulation::PeriodicGrid& grid, std::size_t particleCount);
    void bindBuffers() const;
    void push(double dt, bool movePositions);
    void deposit();
    void solvePotential();
    void computeNodeField();
    void solveFields();

    simulation::PeriodicGrid grid_;
    GpuPicSolver solver_;
    simulation::FftPoissonSolver poisson_;
    std::unique_ptr<GpuPoisson> gpuPoisson_; // for Jacobi and RedBlackSor
    std::size_t particleCount_;
    double weight_;
    int quantumBits_;
    double dt_;
    long steps_ = 0;
    std::unique_ptr<Programs> programs_;
    unsigned buffers_[5] = {};
    std::vector<std::int32_t> zeroQuanta_;
    mutable std::vector<double> chargeDensity_;
    mutable long chargeDensityStep_ = -1; // the step chargeDensity_ belongs to
};

} // namespace aurorawall::components::plasma::gpu
