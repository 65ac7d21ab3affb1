#include "app/gamepad.h"

#include <algorithm>
#include <cmath>

namespace aurorawall::app {

namespace {

using Pad = gl::GamepadState;

// An axis in [-1, 1] with the dead zone removed: 0 within it, then linear up to +-1.
double beyondDeadZone(double axis, double deadZone)
{
    const double magnitude = std::clamp(std::abs(axis), 0.0, 1.0);
    if (magnitude <= deadZone)
        return 0.0;
    return std::copysign((magnitude - deadZone) / (1.0 - deadZone), axis);
}

// A trigger's pressure in [0, 1] (its axis runs from -1 released to +1 pressed), dead zone removed.
double pressure(const Pad& pad, Pad::Axis trigger)
{
    return std::max(0.0, beyondDeadZone(0.5 * (pad.axes[trigger] + 1.0), kTriggerDeadZone));
}

double stick(const Pad& pad, Pad::Axis axis) { return beyondDeadZone(pad.axes[axis], kStickDeadZone); }

double held(const Pad& pad, Pad::Button button) { return pad.buttons[button] ? 1.0 : 0.0; }

} // namespace

GamepadMotion gamepadMotion(const gl::GamepadState& state, const gl::GamepadState& previous, double frameS)
{
    const double dt = std::clamp(frameS, 0.0, kMaxGamepadFrameS);
    GamepadMotion m;
    // Stick y is +1 down: pushing it up (-1) moves forward, looks up.
    m.moveS = glm::dvec3(stick(state, Pad::LeftX), -stick(state, Pad::LeftY),
                         held(state, Pad::DpadUp) - held(state, Pad::DpadDown)) * dt;
    m.turnRightDeg = kLookDegPerS * stick(state, Pad::RightX) * dt;
    m.turnUpDeg = -kLookDegPerS * stick(state, Pad::RightY) * dt;
    m.rollRightDeg = kRollDegPerS * (held(state, Pad::RightBumper) - held(state, Pad::LeftBumper)) * dt;
    m.speedFactor = std::exp2((pressure(state, Pad::RightTrigger) - pressure(state, Pad::LeftTrigger)) * dt);
    m.togglePause = state.buttons[Pad::A] && !previous.buttons[Pad::A];
    return m;
}

} // namespace aurorawall::app
