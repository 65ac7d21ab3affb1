#pragma once
// The frames of a CPU plasma simulation, the box's and the sheet's alike.
#include "components/plasma/simulation/electrostatic_pic.h"

#include <vector>

namespace aurorawall::components::plasma {

// Appends `frames` frames of `sim` to `out`, the first at its current step and each next one
// stepsPerFrame steps later, each as frameOf(the electrons) computes it.
template <class FrameOf>
void recordFrames(simulation::ElectrostaticPic& sim, int frames, int stepsPerFrame, std::vector<float>& out,
                  FrameOf frameOf)
{
    for (int k = 0; k < frames; ++k) {
        if (k > 0)
            for (int n = 0; n < stepsPerFrame; ++n)
                sim.step();
        const std::vector<float> frame = frameOf(sim.electrons());
        out.insert(out.end(), frame.begin(), frame.end());
    }
}

} // namespace aurorawall::components::plasma
