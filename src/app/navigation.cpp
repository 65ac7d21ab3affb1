#include "app/navigation.h"

#include "app/control/orbit.h"
#include "physics/constants.h"
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
    return glm::normalize(orientation * glm::angleAxis(deg * physics::kDegree, ownAxis));
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
    scene::Camera c = camera;
    for (const cluster::InputEvent& event : events) {
        if (event.type == gl::InputEvent::KeyPressed && event.code == 'O') {
            if (pivot_) {
                pivot_.reset();
            } else {
                pivot_ = control::orbitPivot(c, planetRadiusKm_);
                c.speedKmPerS = 0.0;
            }
            continue;
        }
        c = pivot_ ? orbited(c, event) : flown(c, event);
    }
    return c;
}

scene::Camera Navigation::flown(const scene::Camera& camera, const cluster::InputEvent& event)
{
    glm::dvec3 position = camera.positionKm;
    glm::dquat orientation = orientationOf(camera);
    if (event.type == gl::InputEvent::Dragged) {
        // The view follows the pointer: right turns right (negative about up), down looks down.
        orientation = turned(orientation, kUp, -kDragDegPerPx * event.x);
        orientation = turned(orientation, kRight, -kDragDegPerPx * event.y);
        return posed(camera, position, orientation);
    }
    if (event.type != gl::InputEvent::KeyPressed)
        return camera;
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
    default: return camera;
    }
    if (move != glm::dvec3(0.0))
        position = moved(position, orientation, move * kNudgeS);
    return posed(camera, position, orientation);
}

scene::Camera Navigation::orbited(const scene::Camera& camera, const cluster::InputEvent& event)
{
    const double minRadiusKm = planetRadiusKm_ + kMinAltitudeKm;
    if (event.type == gl::InputEvent::Dragged) // the scene follows the pointer
        return control::orbitTurned(camera, *pivot_, -kDragDegPerPx * event.x, kDragDegPerPx * event.y, minRadiusKm);
    if (event.type != gl::InputEvent::KeyPressed)
        return camera;
    switch (event.code) {
    case gl::KeyRight: return control::orbitTurned(camera, *pivot_, kTurnDeg, 0.0, minRadiusKm);
    case gl::KeyLeft: return control::orbitTurned(camera, *pivot_, -kTurnDeg, 0.0, minRadiusKm);
    case gl::KeyUp: return control::orbitTurned(camera, *pivot_, 0.0, kTurnDeg, minRadiusKm);
    case gl::KeyDown: return control::orbitTurned(camera, *pivot_, 0.0, -kTurnDeg, minRadiusKm);
    case 'W': return closer(camera, kNudgeS);
    case 'S': return closer(camera, -kNudgeS);
    case 'E':
    case 'Q': {
        scene::Camera c = camera; // a roll about the view keeps the pivot at the centre
        c.up = glm::normalize(glm::angleAxis((event.code == 'E' ? kTurnDeg : -kTurnDeg) * physics::kDegree, c.forward) * c.up);
        return c;
    }
    case gl::KeyPlus: speedPerS_ = std::min(2.0 * speedPerS_, kMaxSpeedPerS); return camera;
    case gl::KeyMinus: speedPerS_ = std::max(0.5 * speedPerS_, kMinSpeedPerS); return camera;
    default: return camera;
    }
}

scene::Camera Navigation::closer(const scene::Camera& camera, double towardS) const
{
    const double distanceKm = glm::length(*pivot_ - camera.positionKm);
    double to = distanceKm - towardS * speedKmPerS(distanceKm);
    to = std::max(to, std::min(distanceKm, kMinOrbitDistanceKm));
    return control::orbitAtDistance(camera, *pivot_, to, planetRadiusKm_ + kMinAltitudeKm);
}

scene::Camera Navigation::apply(const scene::Camera& camera, const GamepadMotion& motion)
{
    if (pivot_) { // the right stick orbits, the left stick's forward/back approaches, the shoulders roll
        scene::Camera c = control::orbitTurned(camera, *pivot_, motion.turnRightDeg, motion.turnUpDeg,
                                               planetRadiusKm_ + kMinAltitudeKm);
        c.up = glm::normalize(glm::angleAxis(motion.rollRightDeg * physics::kDegree, c.forward) * c.up);
        speedPerS_ = std::clamp(speedPerS_ * motion.speedFactor, kMinSpeedPerS, kMaxSpeedPerS);
        return motion.moveS.y != 0.0 ? closer(c, motion.moveS.y) : c;
    }
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
    const double altitudeKm = scene::altitudeKm(position, planetRadiusKm_);
    glm::dvec3 to = position + orientation * ownMoveS * speedKmPerS(altitudeKm);
    // Never below the ground: back up along the vertical to kMinAltitudeKm.
    const double r = glm::length(to);
    if (r < planetRadiusKm_ + kMinAltitudeKm)
        to *= (planetRadiusKm_ + kMinAltitudeKm) / r;
    return to;
}

} // namespace aurorawall::app
