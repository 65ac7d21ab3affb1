#include "cluster/master_clock.h"

namespace aurorawall::cluster {

MasterClock::MasterClock(const ClockSettings& settings, const scene::Camera& camera, double exposure)
    : settings_(settings), camera_(camera), exposure_(exposure), start_(std::chrono::steady_clock::now())
{
}

FrameState MasterClock::next(bool stopRequested)
{
    FrameState s;
    s.frame = frame_;
    const double elapsed = settings_.realTime
        ? std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count()
        : static_cast<double>(frame_) * settings_.timeStepS;
    s.timeS = settings_.startTimeS + elapsed;
    // The camera flies straight along its view direction (the paper's benchmark path).
    s.cameraPositionKm = camera_.positionKm + camera_.forward * (camera_.speedKmPerS * elapsed);
    s.cameraBack = -camera_.forward;
    s.cameraUp = camera_.up;
    s.cameraRight = glm::cross(camera_.forward, camera_.up);
    s.exposure = exposure_;
    s.quit = stopRequested || (settings_.frames > 0 && frame_ >= settings_.frames);
    ++frame_;
    return s;
}

} // namespace aurorawall::cluster
