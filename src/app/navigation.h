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
//
// O toggles orbiting (control/orbit.h). It starts about the pivot orbitPivot() finds (where the view
// axis meets the ground, or as far along it as the planet's centre is) and holds the camera's flight
// speed at 0. While orbiting, the camera looks at the pivot:
//   arrows: carry the camera kTurnDeg about the pivot, right/left about the pivot's zenith and
//       up/down over the pivot about the camera's right (past the zenith without a flip);
//   a drag turns the scene about the pivot with the pointer, kDragDegPerPx per pixel (drag right:
//       the camera goes left; drag down: it rises);
//   W/S: toward/away from the pivot by kNudgeS seconds at speedPerS x max(distance, 10 m), never
//       closer than kMinOrbitDistanceKm, never below kMinAltitudeKm; Q/E roll about the view, +/- as in
//       flight; the other keys do nothing. A turn that would take the camera below kMinAltitudeKm is
//       not made.
#include "app/gamepad.h"
#include "cluster/frame_message.h"
#include "scene/scene.h"

#include <glm/gtc/quaternion.hpp>

#include <optional>
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
    static constexpr double kMinOrbitDistanceKm = 0.001; // 1 m

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

    // Orbits pivotKm from now on (the caller aims the camera at it: control::aimedAt).
    void orbit(const glm::dvec3& pivotKm) { pivot_ = pivotKm; }
    // Free flight again.
    void stopOrbit() { pivot_.reset(); }
    const std::optional<glm::dvec3>& pivot() const { return pivot_; }

private:
    // One event of free flight.
    scene::Camera flown(const scene::Camera& camera, const cluster::InputEvent& event);
    // One event while orbiting.
    scene::Camera orbited(const scene::Camera& camera, const cluster::InputEvent& event);
    // The camera (orbiting) moved along its view by `towardS` seconds at the speed of its distance.
    scene::Camera closer(const scene::Camera& camera, double towardS) const;

    // `position` moved by ownMoveS seconds at the speed of its altitude along the camera's own axes
    // (right, forward, up), at least kMinAltitudeKm above the sphere.
    glm::dvec3 moved(const glm::dvec3& position, const glm::dquat& orientation, const glm::dvec3& ownMoveS) const;

    double planetRadiusKm_;
    double speedPerS_ = 1.0;
    std::optional<glm::dvec3> pivot_; // set while orbiting
};

} // namespace aurorawall::app
