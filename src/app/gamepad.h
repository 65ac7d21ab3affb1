#pragma once
// Flying the camera with a gamepad (GLFW's standard layout, gl::GamepadState), polled by the master
// once per frame. The sticks and triggers are rates, so a frame's motion is the rate times the frame's
// duration:
//   left stick: move forward/back (up/down) and right/left, at most the navigation's speed
//       (app/navigation.h: speed factor x max(altitude, 10 m) per second); D-pad up/down: climb/descend;
//   right stick: look right/left and up/down, at most kLookDegPerS;
//   left/right shoulder buttons: roll left/right at kRollDegPerS;
//   left/right trigger: the speed factor halves/doubles each second at full pressure;
//   A: pause/play (on the press).
// Sticks have an axial dead zone of kStickDeadZone, triggers of kTriggerDeadZone: within it nothing
// moves; beyond it the deflection is rescaled to reach 1 at full deflection.
#include "gl/context.h"

#include <glm/glm.hpp>

namespace aurorawall::app {

constexpr double kStickDeadZone = 0.15, kTriggerDeadZone = 0.1;
constexpr double kLookDegPerS = 60.0, kRollDegPerS = 30.0;
constexpr double kMaxGamepadFrameS = 0.1; // a longer frame counts as this long (no jump after a stall)

struct GamepadMotion {
    glm::dvec3 moveS{0.0};     // seconds at full speed along the camera's own right, forward, up
    double turnRightDeg = 0.0; // about the camera's up
    double turnUpDeg = 0.0;    // about its right
    double rollRightDeg = 0.0; // about its view
    double speedFactor = 1.0;  // multiplies the navigation's speed factor
    bool togglePause = false;

    // Whether it moves or turns the camera (a camera left alone stays on its keyed path).
    bool movesCamera() const { return moveS != glm::dvec3(0.0) || turnRightDeg != 0.0 || turnUpDeg != 0.0 || rollRightDeg != 0.0; }
};

// The motion of one frame of `frameS` seconds (clamped to [0, kMaxGamepadFrameS]) with the gamepad
// in `state`; `previous` is its state one frame earlier (the A button acts when pressed).
GamepadMotion gamepadMotion(const gl::GamepadState& state, const gl::GamepadState& previous, double frameS);

} // namespace aurorawall::app
