// The curtain polylines' geometry on the sphere (shaders/components/aurora/segment_projection.glsl, shared
// text): the curvature a march reads from three polyline points, against circles of known geodesic
// curvature, in double and in float.
#include "common/glsl.h"

#include <gtest/gtest.h>

#include <cmath>

namespace aurorawall::f32 {
AURORAWALL_GLSL_PRECISION(float)
#include "components/aurora/segment_projection.glsl"
} // namespace aurorawall::f32

namespace aurorawall::f64 {
AURORAWALL_GLSL_PRECISION(double)
#include "components/aurora/segment_projection.glsl"
} // namespace aurorawall::f64

using namespace aurorawall;

namespace {

constexpr double kRadiusKm = 6371.0;

// The point at angle phi of the small circle of angular radius alpha about the unit vector centre.
glm::dvec3 onCircle(glm::dvec3 centre, double alpha, double phi)
{
    const glm::dvec3 e1 = glm::normalize(glm::cross(centre, glm::dvec3(0.3, -0.5, 0.8)));
    const glm::dvec3 e2 = glm::cross(centre, e1);
    return std::cos(alpha) * centre + std::sin(alpha) * (std::cos(phi) * e1 + std::sin(phi) * e2);
}

double arcKm(glm::dvec3 a, glm::dvec3 b)
{
    return kRadiusKm * std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b));
}

// The unit point `km` along a great circle of the planet (kRadiusKm) through a fixed point.
glm::dvec3 alongGreatCircle(double km)
{
    const glm::dvec3 a = glm::normalize(glm::dvec3(1.0, 0.2, 0.1));
    const glm::dvec3 axis = glm::normalize(glm::cross(a, glm::dvec3(0.0, 0.0, 1.0)));
    const double t = km / kRadiusKm;
    return std::cos(t) * a + std::sin(t) * glm::cross(axis, a);
}

} // namespace

// Three points of a small circle of angular radius alpha, whose geodesic curvature is cot(alpha) / R
// towards its centre, read from either end of the segment between two of them (as the march reads the
// point before a segment's start or after its end). The formula is first order in κ d: a circle's third
// point lies off the great circle through the first two by κ d2 (d1 + d2) / 2 to within a relative
// (κ (d1 + d2))² and (d1 + d2)² / R² (the sphere); in float the points' coordinates are rounded to 2^-24,
// which moves the offset by a few of those times R.
TEST(SegmentProjection, CurvatureOfCirclesFromThreePolylinePoints)
{
    const glm::dvec3 centre = glm::normalize(glm::dvec3(0.2, -0.4, 0.9));
    for (double radiusKm : {20.0, 100.0, 400.0, 3000.0})
        for (double spacingKm : {0.5, 2.0, 4.0})
            for (double ratio : {0.5, 1.0, 1.7}) {
                const double alpha = radiusKm / kRadiusKm;
                const double d1 = spacingKm / (kRadiusKm * std::sin(alpha));
                const double d2 = ratio * d1;
                const glm::dvec3 p0 = onCircle(centre, alpha, 0.4);
                const glm::dvec3 p1 = onCircle(centre, alpha, 0.4 + d1);
                const glm::dvec3 p2 = onCircle(centre, alpha, 0.4 + d1 + d2);
                const double kappa = 1.0 / (kRadiusKm * std::tan(alpha));
                const double inner = arcKm(p0, p1), outer = arcKm(p1, p2);
                // The segment p0 → p1 and the point after its end; the segment p1 → p2 and the point before
                // its start. The circle bends towards its centre, so the sign is the centre's side.
                struct Read {
                    glm::dvec3 a, b, corner, beyond;
                    double inner, outer;
                };
                for (const Read& r : {Read{p0, p1, p1, p2, inner, outer}, Read{p1, p2, p1, p0, outer, inner}}) {
                    const glm::dvec3 normal = f64::segmentNormal(r.a, r.b);
                    const double expected = (glm::dot(centre, normal) > 0.0 ? 1.0 : -1.0) * kappa;
                    const double span = r.inner + r.outer;
                    const double firstOrder = kappa * (std::pow(kappa * span, 2) + std::pow(span / kRadiusKm, 2));
                    const double rounding = 16.0 * std::ldexp(1.0, -24) * 2.0 * kRadiusKm / (r.outer * span);
                    // The polyline's largest turn, twice this corner's (κ (d1 + d2) / 2), does not bind.
                    const double largestTurn = kappa * span;
                    EXPECT_NEAR(f64::polylineCurvature(r.corner, r.beyond, normal, r.inner, r.outer, kRadiusKm,
                                                       largestTurn),
                                expected, firstOrder + 1e-12)
                        << radiusKm << " km circle, " << spacingKm << " km segments, ratio " << ratio;
                    const glm::vec3 a(r.a), b(r.b);
                    const float inFloat = f32::polylineCurvature(glm::vec3(r.corner), glm::vec3(r.beyond),
                                                                 f32::segmentNormal(a, b), float(r.inner),
                                                                 float(r.outer), float(kRadiusKm),
                                                                 float(largestTurn));
                    EXPECT_NEAR(inFloat, expected, firstOrder + rounding)
                        << radiusKm << " km circle, " << spacingKm << " km segments, ratio " << ratio << " (float)";
                }
            }
}

// A great circle does not bend, and a polyline's last segment with no point beyond gives no curvature
// (the march reads its own end point: beyond == corner).
TEST(SegmentProjection, StraightAndDegenerateReadsGiveNoCurvature)
{
    const glm::dvec3 normal = f64::segmentNormal(alongGreatCircle(0.0), alongGreatCircle(2.0));
    const glm::dvec3 corner = alongGreatCircle(2.0);
    EXPECT_NEAR(f64::polylineCurvature(corner, alongGreatCircle(4.0), normal, 2.0, 2.0, kRadiusKm, 0.01), 0.0, 1e-9);
    EXPECT_EQ(f64::polylineCurvature(corner, corner, normal, 2.0, 0.0, kRadiusKm, 0.01), 0.0);
}

// Next to a segment of 0.1 m, a point 0.6 m across (a float point's rounding, 1e-7 R) would read as a
// turn of 0.6 / 0.1 rad: the curvature is held to the polyline's largest turn over the two segments.
TEST(SegmentProjection, CurvatureNextToATinySegmentIsHeldToTheLargestTurn)
{
    const glm::dvec3 normal = f64::segmentNormal(alongGreatCircle(0.0), alongGreatCircle(2.0));
    const double largestTurn = 0.01;
    for (double side : {1.0, -1.0}) {
        const glm::dvec3 beyond = glm::normalize(alongGreatCircle(2.0001) + side * 1e-7 * normal);
        const double bound = 2.0 * largestTurn / 2.0001;
        EXPECT_NEAR(f64::polylineCurvature(alongGreatCircle(2.0), beyond, normal, 2.0, 1e-4, kRadiusKm,
                                           largestTurn),
                    side * bound, 1e-12);
    }
}
