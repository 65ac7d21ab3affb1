#pragma once
// The camera orbiting a point (the pivot): it looks at the pivot and turns about it at a fixed
// distance, or moves along its view toward or away from it. Every turn is one rotation about an axis
// through the pivot applied to the camera's position, view and up together, so the pivot stays at the
// centre of the view at the same distance, and nothing depends on angles about a fixed axis: passing
// over the pivot's zenith is as smooth as any other turn. Planet frame of common/planet_frame.h, km.
#include "scene/scene.h"

namespace aurorawall::app::control {

// The point to orbit when orbiting starts from `camera`: where its view axis first meets the ground
// (the sphere of radius planetRadiusKm) ahead of it; when the axis misses the planet, the point on
// the axis as far from the camera as the planet's centre is.
glm::dvec3 orbitPivot(const scene::Camera& camera, double planetRadiusKm);

// `camera` turned, where it stands, to look at `pivotKm`: up is the camera's zenith made perpendicular
// to the view (looking straight up or down: its present up made perpendicular). It holds still (speed
// 0). The camera must not be at the pivot.
scene::Camera aimedAt(const scene::Camera& camera, const glm::dvec3& pivotKm);

// `camera` (looking at `pivotKm`) carried about the pivot: rightDeg to its right about the pivot's
// zenith (the axis through the planet's centre and the pivot, taken on the side of the camera's up,
// so that "right" is the camera's right also upside down), then upDeg over the pivot about the
// camera's right. A turn that would take the camera below minRadiusKm from the planet's centre is
// not made.
scene::Camera orbitTurned(const scene::Camera& camera, const glm::dvec3& pivotKm, double rightDeg, double upDeg,
                          double minRadiusKm);

// `camera` (looking at `pivotKm`) moved along its view to distanceKm from the pivot, or, if the way
// there passes below minRadiusKm from the planet's centre, to where it reaches that radius.
scene::Camera orbitAtDistance(const scene::Camera& camera, const glm::dvec3& pivotKm, double distanceKm,
                              double minRadiusKm);

} // namespace aurorawall::app::control
