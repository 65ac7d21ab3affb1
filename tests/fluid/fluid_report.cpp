// The cost and the diagnostics quoted in docs/fluid.md (benchmark; not run by ctest):
// run time of simulateCurtainDetail for the default and the two quality knobs, one core.
#include "fluid/curtain_detail.h"

#include <chrono>
#include <cstdio>
#include <ctime>

using namespace aurorawall::fluid;

int main()
{
    struct Knob {
        const char* name;
        int nx, ny, stepsPerFrame;
    };
    for (const Knob& knob : {Knob{"low", 256, 64, 3}, Knob{"default", 512, 128, 6}, Knob{"high", 1024, 256, 12}}) {
        CurtainDetailSpec spec;
        spec.nx = knob.nx;
        spec.ny = knob.ny;
        spec.stepsPerFrame = knob.stepsPerFrame;
        const std::clock_t cpu0 = std::clock();
        const auto wall0 = std::chrono::steady_clock::now();
        const FluxFrames frames = simulateCurtainDetail(spec);
        const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
        const double cpu = double(std::clock() - cpu0) / CLOCKS_PER_SEC;
        std::printf("%-7s %4dx%-3d %2d steps/frame %3d steps: %.3f s wall, %.3f s cpu, %zu floats\n", knob.name, knob.nx,
                    knob.ny, knob.stepsPerFrame, knob.stepsPerFrame * (spec.frames - 1), wall, cpu, frames.flux.size());
    }

    const CurtainDetailSpec spec;
    CurtainFlow flow(spec);
    int cycles = 0, steps = 0, worst = 0;
    for (int k = 1; k < spec.frames; ++k)
        for (int n = 0; n < spec.stepsPerFrame; ++n) {
            const int c = flow.step(spec.timeBetweenFramesS / spec.stepsPerFrame).cycles();
            cycles += c;
            worst = c > worst ? c : worst;
            ++steps;
        }
    std::printf("default: %.2f V-cycles per projection on average, %d at most\n", double(cycles) / steps, worst);
}
