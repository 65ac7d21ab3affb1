#pragma once
// Curtain footprints on the sphere (Lawlor & Genetti 2011, §1 and §2: "2D spline curve footprints").
// A footprint is a centripetal Catmull–Rom spline through latitude/longitude control points:
// the spline interpolates the control points' unit vectors in 3D (centripetal knots, so no cusps
// or self-intersections however unevenly they are spaced) and is renormalized onto the sphere.
// sampleCurtain turns it into a dense polyline of great-circle arcs with the spline's arclength.
// Planet frame of scene::planetPoint: z toward the north pole, x toward longitude 180°, y toward 90° W.
#include "common/planet_frame.h"

#include <glm/glm.hpp>

#include <vector>

namespace aurorawall::components::aurora::physics {

// Unit vector of geographic latitude/longitude in degrees, (−cos φ cos λ, −cos φ sin λ, sin φ): the
// planet frame's one formula (common/planet_frame.h), also behind scene::planetPoint.
using aurorawall::common::unitFromLatLon;

// Inverse of unitFromLatLon for a unit vector: (latitude, longitude) in degrees, longitude in [−180°, 180°].
glm::dvec2 latLonFromUnit(const glm::dvec3& unit);

// A curtain footprint sampled into a dense polyline. Consecutive points are joined by great-circle
// arcs no longer than the spacing asked for.
struct CurtainPolyline {
    double planetRadiusKm = 0.0;
    std::vector<glm::dvec3> points;      // unit vectors on the spline
    std::vector<double> arclengthKm;     // arclength of the spline (on the sphere of planetRadiusKm) from points[0]
    std::vector<glm::dvec3> normals;     // unit lateral normal cross(point, tangent): tangent to the sphere,
                                         // perpendicular to the curve, to the left of the direction of travel
                                         // seen from above
    std::vector<int> controlPointIndex;  // points[controlPointIndex[k]] is control point k (exactly)
};

// Samples the centripetal Catmull–Rom spline through latLonDeg (≥ 2 points; consecutive points distinct
// and less than 90° apart) at equal arclength steps of at most spacingKm within each span between
// control points. The end spans use the reflected phantom points 2P_0 − P_1 and 2P_{n−1} − P_{n−2}, so
// points on one great circle give that great circle. Throws std::invalid_argument on bad input.
CurtainPolyline sampleCurtain(const std::vector<glm::dvec2>& latLonDeg, double planetRadiusKm, double spacingKm);

// Keyframe interpolation: each control point moves along the great circle from a[k] to b[k]
// (spherical linear interpolation, Shoemake 1985), so longitude wrap-around is harmless.
// w = 0 gives a, w = 1 gives b. Throws std::invalid_argument if the counts differ or a pair is antipodal.
std::vector<glm::dvec2> interpolateControlPoints(const std::vector<glm::dvec2>& a, const std::vector<glm::dvec2>& b,
                                                 double w);

// C1 ease between keyframe times: x = clamp((t − t0)/(t1 − t0), 0, 1), smoothstep x²(3 − 2x)
// (GLSL smoothstep, OpenGL Shading Language 4.60 §8.3). Requires t1 > t0.
double smoothWeight(double t, double t0, double t1);

} // namespace aurorawall::components::aurora::physics
