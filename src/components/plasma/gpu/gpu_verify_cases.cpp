#include "components/plasma/gpu/gpu_verify_cases.h"

#include "components/plasma/simulation/plasma_parameters.h"

#include <glm/geometric.hpp>

#include <utility>

namespace aurorawall::components::plasma::gpu {
namespace {

class GpuRun : public simulation::PicRun {
public:
    GpuRun(const simulation::PeriodicGrid& grid, const simulation::Particles& electrons, glm::dvec3 magneticField, double dt,
           const std::string& shaderDir, GpuPicSolver solver)
        : pic_(grid, electrons, magneticField, dt, shaderDir, glm::dvec3(0.0), solver),
          particleMass_(simulation::kElectronMass * electrons.weight)
    {
    }
    void step() override { pic_.step(); }
    // As ElectrostaticPic::step: ½ Σ ρ φ ΔV at step n and Σ ½ m (|v_{n−1/2}|² + |v_{n+1/2}|²)/2, here
    // from ρ of the fixed-point sums (double) and the float φ and velocities read back.
    simulation::StepEnergies stepWithEnergies() override
    {
        simulation::StepEnergies energies;
        const std::vector<double>& rho = pic_.chargeDensity();
        const std::vector<double> phi = pic_.potential();
        for (std::size_t n = 0; n < phi.size(); ++n)
            energies.field += 0.5 * rho[n] * phi[n] * pic_.grid().cellVolume();
        const std::vector<glm::dvec3> before = pic_.velocities();
        pic_.step();
        const std::vector<glm::dvec3> after = pic_.velocities();
        for (std::size_t p = 0; p < before.size(); ++p)
            energies.kinetic += 0.25 * particleMass_ * (glm::dot(before[p], before[p]) + glm::dot(after[p], after[p]));
        return energies;
    }
    const std::vector<glm::dvec3>& nodeField() override
    {
        if (fieldStep_ != pic_.stepCount()) {
            field_ = pic_.nodeField();
            fieldStep_ = pic_.stepCount();
        }
        return field_;
    }
    std::vector<glm::dvec3> positions() override { return pic_.positions(); }
    std::vector<glm::dvec3> velocities() override { return pic_.velocities(); }
    std::vector<double> chargeDensity() override { return pic_.chargeDensity(); }

private:
    GpuPic pic_;
    double particleMass_; // kg, of one macroparticle
    std::vector<glm::dvec3> field_;
    long fieldStep_ = -1; // the step field_ belongs to
};

} // namespace

GpuPicDevice::GpuPicDevice(std::string shaderDir, GpuPicSolver solver)
    : shaderDir_(std::move(shaderDir)), solver_(solver)
{
}

std::unique_ptr<simulation::PicRun> GpuPicDevice::run(const simulation::PeriodicGrid& grid, const simulation::Particles& electrons,
                                          glm::dvec3 magneticField, double dt) const
{
    return std::make_unique<GpuRun>(grid, electrons, magneticField, dt, shaderDir_, solver_);
}

std::vector<glm::dvec3> GpuPicDevice::testParticleVelocities(glm::dvec3 start, glm::dvec3 electricField,
                                                              glm::dvec3 magneticField, double dt, long steps) const
{
    const simulation::PeriodicGrid grid(1, {8, 1, 1}, {1.0, 1.0, 1.0});
    simulation::Particles electron;
    electron.position = {glm::dvec3(4.0, 0.5, 0.5)};
    electron.velocity = {start};
    electron.weight = 0.0;
    GpuPic pic(grid, electron, magneticField, dt, shaderDir_, electricField);
    std::vector<glm::dvec3> v;
    for (long n = 0; n <= steps; ++n) {
        v.push_back(pic.velocities()[0]);
        pic.step();
    }
    return v;
}

std::vector<simulation::VerifyRow> GpuPicDevice::settings(std::size_t particles, int dimension) const
{
    return {{"quantum_bits", double(depositQuantumBits(particles, dimension)), std::nullopt}};
}

} // namespace aurorawall::components::plasma::gpu
