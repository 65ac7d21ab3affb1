// The fluid detail's knob in the sweep of `aurorawall accuracy --scene`: the simulation's cells.
#include "components/fluid_detail/fluid_detail.h"
#include "components/tools.h"

#include <string>

namespace aurorawall::components::fluid_detail::tools {

namespace {

// 256x64 to 1024x256 cells (along x across, four to one as the defaults): the frames themselves
// change, so the CPU reference samples the finest frames too.
std::vector<SweepKnob> sweepKnobs(const scene::Scene& scene)
{
    if (!scene.has(Settings::kComponent))
        return {};
    auto cells = [](int along) {
        return [along](scene::Scene& s) {
            s.settings<Settings>().cellsAlong = along;
            s.settings<Settings>().cellsAcross = along / 4;
        };
    };
    SweepKnob knob{"fluid_cells", {}, cells(1024), "1024x256 fluid cells", true, "", ""};
    for (int along : {256, 512, 1024})
        knob.values.push_back({std::to_string(along) + "x" + std::to_string(along / 4), cells(along)});
    return {knob};
}

} // namespace

const Tools& registered()
{
    static const Tools tools{{}, {}, {}, nullptr, "", {}, sweepKnobs};
    return tools;
}

} // namespace aurorawall::components::fluid_detail::tools
