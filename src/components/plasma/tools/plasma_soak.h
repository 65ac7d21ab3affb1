#pragma once
// `aurorawall plasma soak --scene FILE [--steps N] [--every M] [--device cpu|gpu]`: the long-run check of
// a scene's plasma simulations (the strip, and the box with kind = "box"), loaded as the component
// loads them, stepped far beyond the frames the component keeps (docs/PLASMA.md, "Soak").
#include "components/plasma/plasma.h"
#include "components/plasma/simulation/particles.h"
#include "components/plasma/simulation/periodic_grid.h"

#include <glm/vec3.hpp>

#include <iosfwd>
#include <string>
#include <vector>

namespace aurorawall::components::plasma::tools {

// One of a scene's simulations at time 0, as the component starts it.
struct SoakSimulation {
    std::string name; // "strip" or "box"
    simulation::PeriodicGrid grid;
    simulation::Particles electrons;
    glm::dvec3 magneticField; // T
    double dt;                // s
};

// The strip (electron_sheet.h, from sheetFramesSpec) and, with kind = "box", the box's two seeded
// beams (box_frames.h, from boxFramesSpec).
std::vector<SoakSimulation> soakSimulations(const Settings& plasma);

// Throws std::runtime_error "NAME: step N: QUANTITY ..." at the first position that is not finite or
// lies outside the box [0, L] (per axis, m), or the first velocity or node field value that is not finite.
void checkSoakState(const std::string& name, long step, const std::vector<glm::dvec3>& positions,
                    const std::vector<glm::dvec3>& velocities, const std::vector<glm::dvec3>& nodeField,
                    glm::dvec3 box);

// argv[0] is the action's name ("soak"). Prints CSV
// simulation,step,time_s,field_energy_j,kinetic_energy_j,total_energy_j,max_abs_e_v_per_m,max_density_over_n0
// at step 0, every M steps and at step N, for each simulation in turn, after checking that every
// electron's position is finite and inside the box and every velocity and node field value finite.
// Returns the exit status (cli/exit_status.h): 1 with one line naming the simulation, step and
// quantity at the first check that fails; 2 for a bad option or a scene without plasma.
int runPlasmaSoakCommand(int argc, char** argv, std::ostream& out, std::ostream& err);

} // namespace aurorawall::components::plasma::tools
