// The plasma's commands, and its knob in the sweep of `aurorawall accuracy --scene`.
#include "components/plasma/plasma.h"
#include "components/plasma/tools/plasma_command.h"
#include "components/tools.h"

#include <string>

namespace aurorawall::components::plasma::tools {

namespace {

// The box's march, 1 to 16 midpoint steps per cell side (with kind = "box"; "curls" marches no box).
// The CPU reference integrates the box's column exactly, so the knob refines the GPU's march only.
std::vector<SweepKnob> sweepKnobs(const scene::Scene& scene)
{
    if (!scene.has(Settings::kComponent) || scene.settings<Settings>().kind != Settings::Kind::Box)
        return {};
    auto steps = [](int perCell) { return [perCell](scene::Scene& s) { s.settings<Settings>().boxStepsPerCell = perCell; }; };
    SweepKnob knob{"box_steps_per_cell", {}, steps(16), "16 steps per cell", false,
                   ", plasma box 16 steps per cell", ", the plasma box's column exact"};
    for (int perCell : {1, 2, 4, 8, 16})
        knob.values.push_back({std::to_string(perCell), steps(perCell)});
    return {knob};
}

} // namespace

const Tools& registered()
{
    static const Tools tools{
        {{"plasma",
          "the particle-in-cell plasma: verify [--case NAME] against theory, soak --scene F (long\n"
          "            runs of a scene's plasma), accuracy (error against run time)",
          runPlasmaCommand}},
        {},
        {},
        nullptr,
        "",
        {},
        sweepKnobs};
    return tools;
}

} // namespace aurorawall::components::plasma::tools
