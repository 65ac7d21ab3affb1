#pragma once
// The twilight test case of the several-lights sky and its error measure.
#include "physics/atmosphere/airmass_accuracy.h"
#include "physics/atmosphere/sky.h"

#include <vector>

namespace aurorawall::physics::atmosphere {

// Errors of sky radiance are relative per primary, |L − L_ref| / max(L_ref, 1e-6 cd/m²): below 1% of a
// natural night sky (1e-4 cd/m²) only absolute errors count, so a direction in the Earth's shadow
// (L_ref ≈ 0) is no error when its value is invisible too.
inline constexpr double kSkyRadianceFloor = 1e-6;

// The converged reference: double precision, nested march with this many outer and inner steps
// (`aurorawall accuracy --sky` prints its distance from a run with half as many of each).
inline constexpr int kSkyReferenceViewSteps = 1024;
inline constexpr int kSkyReferenceLightSteps = 1024;

// The observer's local frame at the ground, rotated off the coordinate axes (unit vectors, planet frame).
struct TwilightFrame {
    glm::dvec3 up, north, east;
};
TwilightFrame twilightFrame();

// The unit vector at the given azimuth (degrees from north toward east) and elevation in that frame.
glm::dvec3 twilightDirection(double azimuthDegrees, double elevationDegrees);

// A ground observer eyeHeightKm above the ground looking at azimuths 0, 45, …, 315° (0° is toward the
// setting Sun) and elevations 0, 1, 3, 10, 30, 60°, plus the zenith: 49 rays, tMax unbounded.
std::vector<SkyView> twilightViews(double eyeHeightKm);

// `count` (1–8) positions of the setting Sun, a time lapse: elevation −2° down to −8° and azimuth 0° to
// 20° in equal steps (one position: −5°, 10°), each white with 1.28e5/count lux (the solar illuminance
// shared out, so that every count gives about the same sky).
std::vector<SkyLight> twilightSuns(int count);

// Radiance of every view in the given precision (kSkyMaxLights lights at most).
std::vector<glm::dvec3> skyRadiances(const std::vector<SkyView>& views, const SkyAtmosphereParameters& atmosphere,
                                     const std::vector<SkyLight>& lights, SkyLightMethod method, int viewSteps,
                                     int lightSteps, AirmassPrecision precision);

// Relative errors (kSkyRadianceFloor) over every view and primary; worstIndex is the view's index.
RelativeErrors skyErrors(const std::vector<glm::dvec3>& values, const std::vector<glm::dvec3>& reference);

} // namespace aurorawall::physics::atmosphere
