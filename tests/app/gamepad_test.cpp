// The gamepad's mapping (app/gamepad.h) with synthetic states: no input and the dead zones give no
// motion, full deflection the documented rates, A acts once per press; and the navigation flies it.
#include "app/control/geographic_camera.h"
#include "app/gamepad.h"
#include "app/navigation.h"
#include "physics/constants.h"

#include <gtest/gtest.h>

#include <cmath>

namespace aurorawall::app {
namespace {

using Pad = gl::GamepadState;
constexpr double kFrameS = 0.05;

void expectNoMotion(const GamepadMotion& m)
{
    EXPECT_EQ(m.moveS, glm::dvec3(0.0));
    EXPECT_EQ(m.turnRightDeg, 0.0);
    EXPECT_EQ(m.turnUpDeg, 0.0);
    EXPECT_EQ(m.rollRightDeg, 0.0);
    EXPECT_EQ(m.speedFactor, 1.0);
    EXPECT_FALSE(m.togglePause);
}

TEST(Gamepad, NoInputNoMotion)
{
    const Pad rest; // sticks centred, triggers released (-1), no button
    expectNoMotion(gamepadMotion(rest, rest, kFrameS));
}

TEST(Gamepad, WithinTheDeadZonesNoMotion)
{
    // Just inside: 0.99 of the dead zone (the axes are floats; the dead zone's float may lie beyond it).
    Pad pad;
    for (int axis : {Pad::LeftX, Pad::LeftY, Pad::RightX, Pad::RightY})
        pad.axes[axis] = (axis % 2 ? -1.0f : 1.0f) * static_cast<float>(0.99 * kStickDeadZone);
    // A trigger's pressure is (axis + 1) / 2.
    pad.axes[Pad::LeftTrigger] = pad.axes[Pad::RightTrigger] = static_cast<float>(2.0 * 0.99 * kTriggerDeadZone - 1.0);
    expectNoMotion(gamepadMotion(pad, pad, kFrameS));
}

TEST(Gamepad, FullDeflectionGivesTheRates)
{
    Pad pad;
    pad.axes[Pad::LeftX] = 1.0f;   // right
    pad.axes[Pad::LeftY] = -1.0f;  // pushed up: forward
    pad.axes[Pad::RightX] = -1.0f; // look left
    pad.axes[Pad::RightY] = -1.0f; // look up
    pad.buttons[Pad::DpadUp] = 1;
    pad.buttons[Pad::RightBumper] = 1;
    pad.axes[Pad::RightTrigger] = 1.0f;
    const GamepadMotion m = gamepadMotion(pad, pad, kFrameS);
    EXPECT_EQ(m.moveS, glm::dvec3(kFrameS, kFrameS, kFrameS));
    EXPECT_DOUBLE_EQ(m.turnRightDeg, -kLookDegPerS * kFrameS);
    EXPECT_DOUBLE_EQ(m.turnUpDeg, kLookDegPerS * kFrameS);
    EXPECT_DOUBLE_EQ(m.rollRightDeg, kRollDegPerS * kFrameS);
    EXPECT_DOUBLE_EQ(m.speedFactor, std::exp2(kFrameS)); // doubling per second
    EXPECT_FALSE(m.togglePause);                        // A not pressed

    // The opposite deflections, and both shoulders cancel.
    pad.axes[Pad::LeftX] = -1.0f;
    pad.buttons[Pad::DpadUp] = 0;
    pad.buttons[Pad::DpadDown] = 1;
    pad.buttons[Pad::LeftBumper] = 1;
    pad.axes[Pad::RightTrigger] = -1.0f;
    pad.axes[Pad::LeftTrigger] = 1.0f;
    const GamepadMotion back = gamepadMotion(pad, pad, kFrameS);
    EXPECT_EQ(back.moveS, glm::dvec3(-kFrameS, kFrameS, -kFrameS));
    EXPECT_EQ(back.rollRightDeg, 0.0);
    EXPECT_DOUBLE_EQ(back.speedFactor, std::exp2(-kFrameS));
}

TEST(Gamepad, BeyondTheDeadZoneRisesLinearly)
{
    Pad pad;
    pad.axes[Pad::LeftY] = 0.575f; // halfway from the dead zone 0.15 to 1: half speed back
    const GamepadMotion m = gamepadMotion(pad, pad, kFrameS);
    EXPECT_NEAR(m.moveS.y, -0.5 * kFrameS, 1e-8); // 1e-8: the float axis
    EXPECT_EQ(m.moveS.x, 0.0);
}

TEST(Gamepad, LongFramesAreClampedAndAActsOnItsPress)
{
    Pad pad, before;
    pad.axes[Pad::LeftY] = -1.0f;
    pad.buttons[Pad::A] = 1;
    const GamepadMotion stalled = gamepadMotion(pad, before, 5.0);
    EXPECT_EQ(stalled.moveS.y, kMaxGamepadFrameS);
    EXPECT_TRUE(stalled.togglePause);
    EXPECT_FALSE(gamepadMotion(pad, pad, kFrameS).togglePause); // still held
    expectNoMotion(gamepadMotion(before, pad, kFrameS));        // released
}

TEST(Gamepad, NavigationFliesTheMotion)
{
    const double r = 6371.0;
    const scene::Camera c = control::cameraAt({65.0, 25.0, 100.0, 30.0, 10.0}, r, 0.0);
    Navigation nav(r);
    GamepadMotion forward;
    forward.moveS = {0.0, kFrameS, 0.0}; // 1 /s x 100 km x 0.05 s = 5 km along the view
    const scene::Camera moved = nav.apply(c, forward);
    EXPECT_NEAR(glm::length(moved.positionKm - (c.positionKm + c.forward * 5.0)), 0.0, 1e-9);
    EXPECT_NEAR(glm::length(moved.forward - c.forward), 0.0, 1e-15);

    GamepadMotion look;
    look.turnUpDeg = 3.0;
    look.speedFactor = 1e6; // beyond the bound
    const scene::Camera up = nav.apply(c, look);
    EXPECT_NEAR(std::acos(glm::dot(up.forward, c.forward)) / aurorawall::physics::kDegree, 3.0, 1e-9);
    EXPECT_EQ(nav.speedPerS(), Navigation::kMaxSpeedPerS);
    EXPECT_EQ(nav.apply(c, GamepadMotion{}).positionKm, c.positionKm);
}

} // namespace
} // namespace aurorawall::app
