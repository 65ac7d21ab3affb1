#include "app/control/geographic_camera.h"

#include "physics/constants.h"

#include <algorithm>
#include <cmath>

namespace aurorawall::app::control {

GeographicPose poseOf(const scene::Camera& camera, double planetRadiusKm)
{
    GeographicPose p;
    const double r = glm::length(camera.positionKm);
    const glm::dvec3 up = camera.positionKm / r;
    // Inverse of unitFromLatLon: (-cos lat cos lon, -cos lat sin lon, sin lat).
    p.latitudeDeg = std::asin(std::clamp(up.z, -1.0, 1.0)) / physics::kDegree;
    p.longitudeDeg = std::atan2(-up.y, -up.x) / physics::kDegree;
    p.altitudeKm = r - planetRadiusKm;
    const scene::LocalFrame local = scene::localFrame(p.latitudeDeg, p.longitudeDeg);
    const glm::dvec3 f = glm::normalize(camera.forward);
    p.pitchDeg = std::asin(std::clamp(glm::dot(f, local.up), -1.0, 1.0)) / physics::kDegree;
    const double heading = std::atan2(glm::dot(f, local.east), glm::dot(f, local.north)) / physics::kDegree;
    p.headingDeg = heading < 0 ? heading + 360.0 : heading;
    if (p.headingDeg >= 360.0) // -1e-15 + 360 rounds to 360
        p.headingDeg = 0.0;
    return p;
}

scene::Camera cameraAt(const GeographicPose& pose, double planetRadiusKm, double speedKmPerS)
{
    scene::Camera c;
    c.positionKm = scene::planetPoint(pose.latitudeDeg, pose.longitudeDeg, planetRadiusKm + pose.altitudeKm);
    const scene::LocalFrame local = scene::localFrame(pose.latitudeDeg, pose.longitudeDeg);
    const double heading = pose.headingDeg * physics::kDegree, pitch = pose.pitchDeg * physics::kDegree;
    const glm::dvec3 horizontal = std::cos(heading) * local.north + std::sin(heading) * local.east;
    c.forward = glm::normalize(std::cos(pitch) * horizontal + std::sin(pitch) * local.up);
    c.up = glm::cross(glm::cross(c.forward, local.up), c.forward);
    if (glm::length(c.up) < 1e-9)
        c.up = pitch > 0 ? -horizontal : horizontal;
    c.up = glm::normalize(c.up - c.forward * glm::dot(c.up, c.forward));
    c.speedKmPerS = speedKmPerS;
    return c;
}

} // namespace aurorawall::app::control
