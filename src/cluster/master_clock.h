#pragma once
// The master's side of the frame loop: it alone reads the clock and moves the camera, and
// turns them into the FrameState every rank renders.
#include "cluster/frame_state.h"
#include "scene/scene.h"

#include <chrono>
#include <cstdint>

namespace aurorawall::cluster {

struct ClockSettings {
    std::uint64_t frames = 1;  // frames to render; 0: until a window is closed
    double startTimeS = 0.0;
    double timeStepS = 1.0 / 30.0; // animation time per frame (fixed step: reproducible)
    bool realTime = false;         // animation time follows the wall clock instead
};

class MasterClock {
public:
    MasterClock(const ClockSettings& settings, const scene::Camera& camera, double exposure);

    // The state of the next frame; quit is set once the frame count is reached or `stopRequested`.
    FrameState next(bool stopRequested);

private:
    ClockSettings settings_;
    scene::Camera camera_;
    double exposure_;
    std::uint64_t frame_ = 0;
    std::chrono::steady_clock::time_point start_;
};

} // namespace aurorawall::cluster
