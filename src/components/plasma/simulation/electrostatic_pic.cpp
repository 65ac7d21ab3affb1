#include "components/plasma/simulation/electrostatic_pic.h"

#include "common/glsl.h"
#include "components/plasma/simulation/particle_mesh.h"
#include "components/plasma/simulation/plasma_parameters.h"

#include <glm/geometric.hpp>

#include <stdexcept>
#include <utility>

namespace aurorawall::components::plasma::simulation {
namespace {
namespace f64 {
AURORAWALL_GLSL_PRECISION(double)
#include "components/plasma/boris_push.glsl"
} // namespace f64

constexpr double kChargeOverMass = -kElementaryCharge / kElectronMass; // C/kg, the same for a macroparticle

} // namespace

ElectrostaticPic::ElectrostaticPic(const PeriodicGrid& grid, Particles electrons, glm::dvec3 magneticField, double dt,
                                   ParticleShape shape)
    : grid_(grid), poisson_(grid), electrons_(std::move(electrons)), magneticField_(magneticField), dt_(dt),
      shape_(shape)
{
    if (!(dt > 0.0) || electrons_.position.size() != electrons_.velocity.size())
        throw std::invalid_argument("ElectrostaticPic: needs dt > 0 and a velocity per particle");
    solveFields();
    const std::vector<glm::dvec3> e = gatherField(grid_, nodeField_, electrons_.position, shape_);
    for (std::size_t p = 0; p < e.size(); ++p)
        electrons_.velocity[p] = f64::borisVelocity(electrons_.velocity[p], e[p], magneticField_, kChargeOverMass, -0.5 * dt_);
}

void ElectrostaticPic::solveFields()
{
    chargeDensity_ = depositChargeDensity(grid_, electrons_, shape_);
    potential_ = poisson_.solve(chargeDensity_);
    nodeField_ = nodeElectricField(grid_, potential_);
}

StepEnergies ElectrostaticPic::step()
{
    StepEnergies energies;
    for (std::size_t n = 0; n < potential_.size(); ++n)
        energies.field += 0.5 * chargeDensity_[n] * potential_[n] * grid_.cellVolume();

    const double mass = kElectronMass * electrons_.weight;
    const glm::dvec3 box = grid_.boxLength();
    const std::vector<glm::dvec3> e = gatherField(grid_, nodeField_, electrons_.position, shape_);
    for (std::size_t p = 0; p < e.size(); ++p) {
        const glm::dvec3 before = electrons_.velocity[p];
        const glm::dvec3 after = f64::borisVelocity(before, e[p], magneticField_, kChargeOverMass, dt_);
        energies.kinetic += 0.25 * mass * (glm::dot(before, before) + glm::dot(after, after));
        electrons_.velocity[p] = after;
        electrons_.position[p] = f64::leapfrogPosition(electrons_.position[p], after, dt_, box);
    }
    ++steps_;
    solveFields();
    return energies;
}

} // namespace aurorawall::components::plasma::simulation
