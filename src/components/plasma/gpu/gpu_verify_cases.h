#pragma once
// The device of `aurorawall plasma verify --device gpu`: every case of verify_cases.h runs its
// electrons with GpuPic (float, compute shaders) and the step's Poisson solver `solver`, set up and
// analysed as on the CPU. Needs a current GL 4.5 context while its runs live; shaderDir holds
// components/plasma/.
#include "components/plasma/gpu/gpu_pic.h"
#include "components/plasma/simulation/verify_cases.h"

#include <string>

namespace aurorawall::components::plasma::gpu {

class GpuPicDevice : public simulation::PicDevice {
public:
    explicit GpuPicDevice(std::string shaderDir, GpuPicSolver solver = GpuPicSolver::FftCpu);

    std::unique_ptr<simulation::PicRun> run(const simulation::PeriodicGrid& grid, const simulation::Particles& electrons, glm::dvec3 magneticField,
                                double dt) const override;
    // The electron as a GpuPic particle of weight 0 (no field of its own, so the solver does not
    // matter); v_0 is its velocity after GpuPic's start, taken back half a step.
    std::vector<glm::dvec3> testParticleVelocities(glm::dvec3 start, glm::dvec3 electricField, glm::dvec3 magneticField,
                                                   double dt, long steps) const override;
    // The fixed-point deposit's resolution (quantum_bits) of a run of that many particles.
    std::vector<simulation::VerifyRow> settings(std::size_t particles, int dimension) const override;

private:
    std::string shaderDir_;
    GpuPicSolver solver_;
};

} // namespace aurorawall::components::plasma::gpu
