#include "cluster/master_clock.h"

#include <algorithm>

namespace aurorawall::cluster {

MasterClock::MasterClock(const ClockSettings& settings, const scene::Camera& camera, double exposure)
    : settings_(settings), camera_(camera), cameraTimeS_(settings.startTimeS), exposure_(exposure),
      anchorTimeS_(settings.startTimeS), anchorWall_(std::chrono::steady_clock::now()), lastCallWall_(anchorWall_),
      lastTimeS_(settings.startTimeS)
{
}

FrameState MasterClock::next(bool stopRequested)
{
    const auto now = std::chrono::steady_clock::now();
    const auto previousCall = lastCallWall_;
    lastCallWall_ = now;
    // Real time: speed x the wall-clock seconds from the anchor to `wall` (no earlier than the anchor).
    const auto realTimeAt = [&](std::chrono::steady_clock::time_point wall) {
        return anchorTimeS_ + speed_ * std::chrono::duration<double>(std::max(wall, anchorWall_) - anchorWall_).count();
    };
    const auto fixedStepTime = [&](std::uint64_t advances) {
        return anchorTimeS_ + static_cast<double>(advances) * (speed_ * settings_.timeStepS);
    };
    double timeS = lastTimeS_;
    if (jumpPending_) { // steps asked for after the jump count from the time jumped to
        advances_ = paused_ ? stepsPending_ : 0;
        timeS = fixedStepTime(advances_);
        anchorWall_ = now;
        jumpPending_ = false;
    } else if (!paused_ && settings_.realTime) {
        timeS = realTimeAt(previousCall);
    } else if (!paused_ || stepsPending_ > 0) {
        advances_ += paused_ ? stepsPending_ : 1;
        timeS = fixedStepTime(advances_);
    }
    stepsPending_ = 0;
    lastTimeS_ = timeS;

    FrameState s;
    s.frame = frame_;
    s.timeS = timeS;
    // The same expressions the next call evaluates when no command comes between.
    s.nextTimeS = paused_ ? timeS : settings_.realTime ? realTimeAt(now) : fixedStepTime(advances_ + 1);
    const scene::Camera c = camera();
    s.cameraPositionKm = c.positionKm;
    s.cameraBack = -c.forward;
    s.cameraUp = c.up;
    s.cameraRight = glm::cross(c.forward, c.up);
    s.zoom = camera_.path.empty() ? 1.0 : camera_.path.zoomAt(timeS, settings_.wallTanHalfFov);
    s.exposure = exposure_;
    s.quit = stopRequested || (settings_.frames > 0 && frame_ >= settings_.frames);
    ++frame_;
    return s;
}

void MasterClock::reanchor()
{
    if (jumpPending_)
        return;
    anchorTimeS_ = lastTimeS_;
    advances_ = 0;
    anchorWall_ = std::chrono::steady_clock::now();
}

void MasterClock::pause()
{
    reanchor();
    paused_ = true;
}

void MasterClock::play()
{
    reanchor();
    paused_ = false;
}

void MasterClock::setSpeed(double speed)
{
    reanchor();
    speed_ = speed;
}

void MasterClock::step()
{
    if (!paused_)
        return;
    if (settings_.realTime) { // real time has no counted advances: jump by one step
        setTime(timeS() + speed_ * settings_.timeStepS);
        return;
    }
    ++stepsPending_;
}

void MasterClock::setTime(double timeS)
{
    anchorTimeS_ = timeS;
    advances_ = 0;
    stepsPending_ = 0;
    jumpPending_ = true;
}

scene::Camera MasterClock::cameraAt(double timeS) const
{
    scene::Camera c = camera_;
    if (!c.path.empty()) { // a keyed flight: the pose at this animation time, held still
        const scene::CameraFrame frame = c.path.frameAt(timeS);
        c.positionKm = c.path.positionAt(timeS);
        c.forward = frame.forward;
        c.up = frame.up;
        c.path = {};
        return c;
    }
    // The camera flies straight along its view direction (the paper's benchmark path).
    c.positionKm += c.forward * (c.speedKmPerS * (timeS - cameraTimeS_));
    return c;
}

void MasterClock::setCamera(const scene::Camera& camera)
{
    camera_ = camera;
    cameraTimeS_ = timeS();
}

} // namespace aurorawall::cluster
