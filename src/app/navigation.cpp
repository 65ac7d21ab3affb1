#include "app/navigation.h"

#include "common/constants.h"
#include "gl/context.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/quaternion.hpp>

namespace aurorawall::app {

namespace {

// The camera's axes in its own frame: x right, y forward (the view), z up.
const glm::dvec3 kRight{1, 0, 0}, kForward{0, 1, 0}, kUp{0, 0, 1};

// The rotation taking the camera's own axes to the planet frame's right, forward and up.
glm::dquat orientationOf(const scene::Camera& camera)
{
    const glm::dvec3 forward = glm::normalize(camera.forward);
    const glm::dvec3 right = glm::normalize(glm::cross(forward, camera.up));
    const glm::dvec3 up = glm::cross(right, forward);
    return glm::normalize(glm::quat_cast(glm::dmat3(right, forward, up)));
}

// Turns the orientation by `deg` about one of the camera's own axes (right-handed).
glm::dquat turned(const glm::dquat& orientation, const glm::dvec3& ownAxis, double deg)
{
    return glm::normalize(orientation * glm::angleAxis(deg * kDegree, ownAxis));
}

// The camera at `position` with `orientation`, its speed along the view kept.
scene::Camera posed(const scene::Camera& camera, const glm::dvec3& position, const glm::dquat& orientation)
{
    scene::Camera c = camera;
    c.positionKm = position;
    c.forward = orientation * kForward;
    c.up = orientation * kUp;
    return c;
}

} // namespace

double Navigation::speedKmPerS(double altitudeKm) const
{
    return speedPerS_ * std::max(altitudeKm, kMinSpeedAltitudeKm);
}

scene::Camera Navigation::apply(const scene::Camera& camera, const std::vector<cluster::InputEvent>& events)
{
    glm::dvec3 position = camera.positionKm;
    glm::dquat orientation = orientationOf(camera);
    for (const cluster::InputEvent& event : events) {
        if (event.type == gl::InputEvent::Dragged) {
            // The view follows the pointer: right turns right (negative about up), down looks down.
            orientation = turned(orientation, kUp, -kDragDegPerPx * event.x);
            orientation = turned(orientation, kRight, -kDragDegPerPx * event.y);
            continue;
        }
        if (event.type != gl::InputEvent::KeyPressed)
            continue;
        glm::dvec3 move{0.0}; // in the camera's own axes
        switch (event.code) {
        case 'W': move = kForward; break;
        case 'S': move = -kForward; break;
        case 'D': move = kRight; break;
        case 'A': move = -kRight; break;
        case 'R': move = kUp; break;
        case 'F': move = -kUp; break;
        case gl::KeyRight: orientation = turned(orientation, kUp, -kTurnDeg); break;
        case gl::KeyLeft: orientation = turned(orientation, kUp, kTurnDeg); break;
        case gl::KeyUp: orientation = turned(orientation, kRight, kTurnDeg); break;
        case gl::KeyDown: orientation = turned(orientation, kRight, -kTurnDeg); break;
        case 'E': orientation = turned(orientation, kForward, kTurnDeg); break;
        case 'Q': orientation = turned(orientation, kForward, -kTurnDeg); break;
        case gl::KeyPlus: speedPerS_ = std::min(2.0 * speedPerS_, kMaxSpeedPerS); break;
        case gl::KeyMinus: speedPerS_ = std::max(0.5 * speedPerS_, kMinSpeedPerS); break;
        default: break;
        }
        if (move != glm::dvec3(0.0))
            position = moved(position, orientation, move * kNudgeS);
    }
    return posed(camera, position, orientation);
}

scene::Camera Navigation::apply(const scene::Camera& camera, const GamepadMotion& motion)
{
    glm::dquat orientation = orientationOf(camera);
    orientation = turned(orientation, kUp, -motion.turnRightDeg);
    orientation = turned(orientation, kRight, motion.turnUpDeg);
    orientation = turned(orientation, kForward, motion.rollRightDeg);
    speedPerS_ = std::clamp(speedPerS_ * motion.speedFactor, kMinSpeedPerS, kMaxSpeedPerS);
    glm::dvec3 position = camera.positionKm;
    if (motion.moveS != glm::dvec3(0.0))
        position = moved(position, orientation, motion.moveS);
    return posed(camera, position, orientation);
}

glm::dvec3 Navigation::moved(const glm::dvec3& position, const glm::dquat& orientation, const glm::dvec3& ownMoveS) const
{
    const double altitudeKm = glm::length(position) - planetRadiusKm_;
    glm::dvec3 to = position + orientation * ownMoveS * speedKmPerS(altitudeKm);
    // Never below the ground: back up along the vertical to kMinAltitudeKm.
    const double r = glm::length(to);
    if (r < planetRadiusKm_ + kMinAltitudeKm)
        to *= (planetRadiusKm_ + kMinAltitudeKm) / r;
    return to;
}

} // namespace aurorawall::app
