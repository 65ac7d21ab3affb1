#include "accuracy/random_views.h"

#include "physics/constants.h"

#include <algorithm>
#include <cmath>

namespace aurorawall::accuracy {
namespace {

constexpr double kDeg = physics::kPi / 180.0;

struct KindRange {
    const char* name;
    double lowKm, highKm;  // camera altitude
    double siteAngleDeg;   // how far from the scene camera's ground point the camera's may lie
};
constexpr KindRange kKinds[kViewKinds] = {
    {"ground", 0.01, 3.0, 8.0},
    {"inside-layer", 90.0, 250.0, 8.0},
    {"above", 250.0, 1500.0, 8.0},
    {"space", 2000.0, 40000.0, 40.0},
};

// The auroral layer's points the camera looks toward: 100–250 km up, within 8° of the scene camera's
// ground point; the aim then turns by up to 25° so that the point is not always in the middle.
constexpr double kTargetLowKm = 100.0, kTargetHighKm = 250.0, kTargetAngleDeg = 8.0, kAimJitterDeg = 25.0;
constexpr double kSpaceZoomKm = 1000.0;

// A unit vector perpendicular to `v`.
glm::dvec3 anyPerpendicular(glm::dvec3 v)
{
    const glm::dvec3 other = std::abs(v.x) < 0.9 ? glm::dvec3(1.0, 0.0, 0.0) : glm::dvec3(0.0, 1.0, 0.0);
    return glm::normalize(glm::cross(v, other));
}

} // namespace

const char* viewKindName(ViewKind kind) { return kKinds[int(kind)].name; }

RandomViews::RandomViews(std::uint64_t seed, RandomViewSettings settings) : engine_(seed), settings_(settings) {}

double RandomViews::uniform(double low, double high)
{
    return low + (high - low) * (double(engine_() >> 11) * 0x1.0p-53);
}

glm::dvec3 RandomViews::around(glm::dvec3 axis, double maxAngleRad)
{
    const double cosTheta = uniform(std::cos(maxAngleRad), 1.0);
    const double sinTheta = std::sqrt(std::max(0.0, 1.0 - cosTheta * cosTheta));
    const double phi = uniform(0.0, 2.0 * physics::kPi);
    const glm::dvec3 a = glm::normalize(axis), b = anyPerpendicular(a), c = glm::cross(a, b);
    return glm::normalize(cosTheta * a + sinTheta * (std::cos(phi) * b + std::sin(phi) * c));
}

SceneView RandomViews::draw(const SceneView& base, ViewKind kind)
{
    const KindRange& range = kKinds[int(kind)];
    const double radius = settings_.planetRadiusKm;
    const glm::dvec3 anchor = glm::normalize(base.frame.cameraPositionKm);
    const glm::dvec3 camera = around(anchor, range.siteAngleDeg * kDeg) * (radius + uniform(range.lowKm, range.highKm));
    const glm::dvec3 target =
        around(anchor, kTargetAngleDeg * kDeg) * (radius + uniform(kTargetLowKm, kTargetHighKm));
    // From space the layer is small: the view zooms in to show about 1,000 km of it per unit of the
    // wall's field of view, and the aim's turn shrinks with it.
    const double zoom = kind == ViewKind::Space ? std::max(1.0, glm::length(target - camera) / kSpaceZoomKm) : 1.0;
    const glm::dvec3 forward = around(target - camera, std::atan(std::tan(kAimJitterDeg * kDeg) / zoom));
    // Up: the local zenith made perpendicular to the aim, then rolled by a random angle about it.
    glm::dvec3 up = camera - glm::dot(camera, forward) * forward;
    up = glm::length(up) > 1e-9 * radius ? glm::normalize(up) : anyPerpendicular(forward);
    const double roll = uniform(0.0, 2.0 * physics::kPi);
    up = std::cos(roll) * up + std::sin(roll) * glm::cross(forward, up);

    SceneView view = base;
    view.frame.cameraPositionKm = camera;
    view.frame.cameraBack = -forward;
    view.frame.cameraUp = glm::normalize(up);
    view.frame.cameraRight = glm::normalize(glm::cross(forward, view.frame.cameraUp));
    view.frame.zoom *= zoom;
    const bool huge = uniform(0.0, 1.0) < settings_.hugeTimeShare;
    view.frame.timeS += huge ? std::pow(10.0, uniform(4.0, 8.0)) : uniform(0.0, settings_.timeSpanS);
    view.frame.nextTimeS = std::nan("");
    return view;
}

} // namespace aurorawall::accuracy
