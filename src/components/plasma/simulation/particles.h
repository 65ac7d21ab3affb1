#pragma once
// The simulation's electrons as macroparticles: each stands for `weight` real electrons (in 1D and
// 2D, per m² or per m of the unresolved axes), so its charge is −e·weight and its mass mₑ·weight.
#include <glm/vec3.hpp>

#include <vector>

namespace aurorawall::components::plasma::simulation {

struct Particles {
    std::vector<glm::dvec3> position; // m, inside the grid's box
    std::vector<glm::dvec3> velocity; // m/s (the simulation keeps it half a step behind the position)
    double weight = 1.0;              // real electrons per macroparticle
};

} // namespace aurorawall::components::plasma::simulation
