#include "app/control/orbit.h"

#include "physics/constants.h"

#include <cmath>

#include <glm/gtc/quaternion.hpp>

namespace aurorawall::app::control {

namespace {

// The camera rotated by `rotation` about an axis through `pivotKm`: position, view and up together.
scene::Camera rotatedAbout(const scene::Camera& camera, const glm::dvec3& pivotKm, const glm::dquat& rotation)
{
    scene::Camera c = camera;
    c.positionKm = pivotKm + rotation * (camera.positionKm - pivotKm);
    c.forward = glm::normalize(rotation * camera.forward);
    c.up = glm::normalize(rotation * camera.up);
    return c;
}

// The component of `v` perpendicular to the unit vector `axis`.
glm::dvec3 perpendicular(const glm::dvec3& v, const glm::dvec3& axis) { return v - axis * glm::dot(v, axis); }

} // namespace

glm::dvec3 orbitPivot(const scene::Camera& camera, double planetRadiusKm)
{
    const glm::dvec3& p = camera.positionKm;
    const glm::dvec3 f = glm::normalize(camera.forward);
    // |p + t f| = R: t^2 + 2 b t + c = 0 with b = p.f, c = |p|^2 - R^2 > 0 above the ground. The
    // nearer root ahead (b < 0) as c / (-b + sqrt(b^2 - c)), free of cancellation when c << b^2.
    const double b = glm::dot(p, f);
    const double r = glm::length(p);
    const double c = (r - planetRadiusKm) * (r + planetRadiusKm);
    const double discriminant = b * b - c;
    if (b < 0.0 && discriminant >= 0.0)
        return p + f * (c / (-b + std::sqrt(discriminant)));
    return p + f * r;
}

scene::Camera aimedAt(const scene::Camera& camera, const glm::dvec3& pivotKm)
{
    scene::Camera c = camera;
    c.forward = glm::normalize(pivotKm - camera.positionKm);
    // Up: the first of the zenith, the present up and the present view with a part across the new view
    // (the present up and view are perpendicular, so one of them has).
    const glm::dvec3 candidates[] = {glm::normalize(camera.positionKm), camera.up, camera.forward};
    for (const glm::dvec3& candidate : candidates) {
        const glm::dvec3 up = perpendicular(candidate, c.forward);
        if (glm::length(up) > 1e-6) {
            c.up = glm::normalize(up);
            break;
        }
    }
    c.speedKmPerS = 0.0;
    c.path = {};
    return c;
}

scene::Camera orbitTurned(const scene::Camera& camera, const glm::dvec3& pivotKm, double rightDeg, double upDeg,
                          double minRadiusKm)
{
    scene::Camera c = camera;
    if (rightDeg != 0.0) {
        // About the zenith z through the pivot the camera moves at angle x d (view x z): to its right
        // (view x up) when its up leans to z, to its left upside down, hence the sign.
        const glm::dvec3 zenith = glm::normalize(pivotKm);
        const double side = glm::dot(c.up, zenith) >= 0.0 ? 1.0 : -1.0;
        const scene::Camera turned = rotatedAbout(c, pivotKm, glm::angleAxis(rightDeg * physics::kDegree, side * zenith));
        if (glm::length(turned.positionKm) >= minRadiusKm)
            c = turned;
    }
    if (upDeg != 0.0) {
        // About the camera's right r the camera moves at angle x d (-up): a negative angle raises it.
        const glm::dvec3 right = glm::normalize(glm::cross(c.forward, c.up));
        const scene::Camera turned = rotatedAbout(c, pivotKm, glm::angleAxis(-upDeg * physics::kDegree, right));
        if (glm::length(turned.positionKm) >= minRadiusKm)
            c = turned;
    }
    return c;
}

scene::Camera orbitAtDistance(const scene::Camera& camera, const glm::dvec3& pivotKm, double distanceKm,
                              double minRadiusKm)
{
    const glm::dvec3 f = glm::normalize(camera.forward);
    const double from = glm::length(pivotKm - camera.positionKm);
    double to = distanceKm;
    // The camera at pivot - d f is below minRadiusKm for d between the roots of
    // d^2 - 2 k d + c = 0, k = pivot.f, c = |pivot|^2 - minRadius^2 (stable forms of the roots).
    const double k = glm::dot(pivotKm, f);
    const double radius = glm::length(pivotKm);
    const double c = (radius - minRadiusKm) * (radius + minRadiusKm);
    const double discriminant = k * k - c;
    if (discriminant > 0.0) {
        const double q = k + std::copysign(std::sqrt(discriminant), k);
        const double r1 = q, r2 = q != 0.0 ? c / q : 0.0;
        const double nearRoot = std::min(r1, r2), farRoot = std::max(r1, r2);
        const double middle = 0.5 * (nearRoot + farRoot);
        if (to > from && from < middle && to > nearRoot) // backing into the planet
            to = nearRoot;
        else if (to < from && from > middle && to < farRoot) // coming down onto it
            to = farRoot;
    }
    scene::Camera moved = camera;
    moved.positionKm = pivotKm - f * to;
    return moved;
}

} // namespace aurorawall::app::control
