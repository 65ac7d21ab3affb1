#pragma once
// The master's side of the frame loop: it alone keeps the animation time and moves the camera, and
// turns them into the FrameState every rank renders. Time can be paused, sped up or slowed down,
// stepped a frame at a time and set (the wall's remote control, docs/driving.md); each change takes
// effect with the next frame, so every rank sees it in the same broadcast.
#include "cluster/frame_state.h"
#include "scene/scene.h"

#include <chrono>
#include <cstdint>

namespace aurorawall::cluster {

struct ClockSettings {
    std::uint64_t frames = 1;  // frames to render; 0: until a window is closed or the wall is told to quit
    double startTimeS = 0.0;
    double timeStepS = 1.0 / 30.0; // animation time per frame (fixed step: reproducible)
    bool realTime = false;         // animation time follows the wall clock instead
    double wallTanHalfFov = 1.0;   // tan(W/2), W the wall's vertical field of view: a path key's field of
                                   // view becomes the frame's zoom relative to it (scene/camera_path.h)
};

class MasterClock {
public:
    MasterClock(const ClockSettings& settings, const scene::Camera& camera, double exposure);

    // The state of the next frame; quit is set once the frame count is reached or `stopRequested`.
    // Its zoom is the keyed path's at its time, 1 (the wall's own view) for a camera without a path.
    // Playing, the animation time advances by speed x timeStepS per frame; with realTime each frame
    // shows the time of the moment the frame before it began (speed x the wall-clock time since the
    // anchor, one frame behind the clock), so that every frame already knows its successor's time
    // (nextTimeS). Paused it stands still but for the steps asked for.
    FrameState next(bool stopRequested);

    void pause();
    void play();
    bool paused() const { return paused_; }
    // The factor on the time step (or on real time); > 0.
    void setSpeed(double speed);
    double speed() const { return speed_; }
    // While paused: the next frame advances by one frame's animation time (speed x timeStepS).
    void step();
    // The next frame shows exactly this animation time; the clock runs on from it.
    void setTime(double timeS);

    // The animation time shown now: the last frame's, or the one a setTime asked for.
    double timeS() const { return jumpPending_ ? anchorTimeS_ : lastTimeS_; }
    // The camera at timeS(): on its keyed path (scene::CameraPath) if it has one, a still pose without
    // the path; otherwise the scene's camera flown straight along its view (forward at speedKmPerS).
    scene::Camera camera() const { return cameraAt(timeS()); }
    // The same at another animation time (where a jump to that time would put it).
    scene::Camera cameraAt(double timeS) const;
    // Puts the camera there at timeS(); it flies on from there as the animation time runs, along its
    // own path if it has one (a camera without one leaves the scene's keyed path).
    void setCamera(const scene::Camera& camera);

private:
    // Restarts the count of advances from the time shown now, keeping a pending jump.
    void reanchor();

    ClockSettings settings_;
    scene::Camera camera_;          // the camera at cameraTimeS_
    double cameraTimeS_;
    double exposure_;
    std::uint64_t frame_ = 0;
    bool paused_ = false;
    double speed_ = 1.0;
    // Fixed step: time = anchorTimeS_ + advances_ x speed x timeStepS, a product rather than a sum,
    // so that frame n of an unchanged run is startTimeS + n x timeStepS exactly as before.
    double anchorTimeS_;
    std::uint64_t advances_ = 0;
    std::chrono::steady_clock::time_point anchorWall_; // real time: when the anchor time was shown
    std::chrono::steady_clock::time_point lastCallWall_; // real time: when the last frame began
    bool jumpPending_ = true;       // the next frame shows anchorTimeS_ itself (also the first frame)
    std::uint64_t stepsPending_ = 0;
    double lastTimeS_;
};

} // namespace aurorawall::cluster
