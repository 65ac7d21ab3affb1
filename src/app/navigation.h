#pragma once
// Flying the wall's camera from the keyboard and mouse of any rank's windows. The master applies the
// events its ranks gathered (gl::InputEvent, carried as cluster::InputEvent: type, code = key,
// x, y = drag) to the camera before it decides the next frame.
//
// Each key press, or repeat while held, is one nudge in the camera's own axes:
//   W/S forward/back, A/D left/right, R/F up/down: kNudgeS seconds at the speed
//       speedPerS x max(altitude, 10 m), so metres near the ground and thousands of km out at
//       geostationary orbit (35786 km) with one set of keys;
//   arrows: look right/left (about the camera's up) and up/down (about its right) by kTurnDeg;
//   Q/E: roll left/right (about the view) by kTurnDeg;
//   +/-: the speed factor x2 / /2, between kMinSpeedPerS and kMaxSpeedPerS (at most 8 /s, so a
//       nudge moves at most 0.8 of the altitude and can never pass through the planet).
// A drag with the left button looks the same way, kDragDegPerPx per pixel (the view follows the
// pointer). The orientation is a unit quaternion in double; the camera never goes below kMinAltitudeKm.
#include "app/gamepad.h"
#include "cluster/frame_message.h"
#include "scene/scene.h"

#include <glm/gtc/quaternion.hpp>

#include <vector>

namespace aurorawall::app {

class Navigation {
public:
    static constexpr double kNudgeS = 0.1;
    static constexpr double kMinSpeedAltitudeKm = 0.01; // the speed stays 10 m x speedPerS near the ground
    static constexpr double kMinAltitudeKm = 0.001;     // 1 m
    static constexpr double kTurnDeg = 2.0;
    static constexpr double kDragDegPerPx = 0.2;
    static constexpr double kMinSpeedPerS = 1.0 / 1024.0, kMaxSpeedPerS = 8.0;

    explicit Navigation(double planetRadiusKm) : planetRadiusKm_(planetRadiusKm) {}

    // The camera after `events`, oldest first; unknown types and keys change nothing. The speed
    // along the view (speedKmPerS) is kept.
    scene::Camera apply(const scene::Camera& camera, const std::vector<cluster::InputEvent>& events);
    // The camera after one frame's gamepad motion (app/gamepad.h): turned, then moved at the speed
    // of its altitude; the speed factor multiplied, within its bounds.
    scene::Camera apply(const scene::Camera& camera, const GamepadMotion& motion);

    // Translation speed, km/s, at `altitudeKm`: speedPerS() x max(altitude, 10 m).
    double speedKmPerS(double altitudeKm) const;
    // The factor of the altitude per second; 1 at start.
    double speedPerS() const { return speedPerS_; }

private:
    // `position` moved by ownMoveS seconds at the speed of its altitude along the camera's own axes
    // (right, forward, up), at least kMinAltitudeKm above the sphere.
    glm::dvec3 moved(const glm::dvec3& position, const glm::dquat& orientation, const glm::dvec3& ownMoveS) const;

    double planetRadiusKm_;
    double speedPerS_ = 1.0;
};

} // namespace aurorawall::app
