#include "components/aurora/physics/curtain_geometry.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace aurorawall::components::aurora::physics {
namespace {

constexpr double kR = 6371.0;

double angle(const glm::dvec3& a, const glm::dvec3& b)
{
    return 2.0 * std::atan2(glm::length(a - b), glm::length(a + b));
}

// Unevenly spaced control points (1 km to 300 km apart) along a wavy arc at about 65° N.
std::vector<glm::dvec2> wavyCurtain()
{
    return {{64.0, -20.0}, {64.01, -19.98}, {65.5, -15.0}, {64.2, -8.0}, {66.0, -7.5}, {65.0, 0.0}, {65.3, 2.0}};
}

// Total arclength of the spline as the chord sum of a 10 m polyline (chord error (h/ρ)²/24 ≈ 1e-10 here).
double referenceLength(const std::vector<glm::dvec2>& points)
{
    CurtainPolyline fine = sampleCurtain(points, kR, 0.01);
    double sum = 0.0;
    for (size_t k = 1; k < fine.points.size(); ++k)
        sum += kR * angle(fine.points[k - 1], fine.points[k]);
    return sum;
}

TEST(CurtainGeometry, LatLonRoundTripAndPlanetFrame)
{
    EXPECT_NEAR(glm::length(common::unitFromLatLon(0.0, 180.0) - glm::dvec3(1, 0, 0)), 0.0, 1e-15);
    EXPECT_NEAR(glm::length(common::unitFromLatLon(0.0, -90.0) - glm::dvec3(0, 1, 0)), 0.0, 1e-15);
    EXPECT_NEAR(glm::length(common::unitFromLatLon(90.0, 0.0) - glm::dvec3(0, 0, 1)), 0.0, 1e-15);
    for (double lat = -80.0; lat <= 80.0; lat += 20.0)
        for (double lon = -170.0; lon <= 170.0; lon += 34.0) {
            glm::dvec2 back = latLonFromUnit(common::unitFromLatLon(lat, lon));
            EXPECT_NEAR(back.x, lat, 1e-12);
            EXPECT_NEAR(back.y, lon, 1e-12);
        }
}

TEST(CurtainGeometry, PassesThroughControlPoints)
{
    const std::vector<glm::dvec2> control = wavyCurtain();
    CurtainPolyline c = sampleCurtain(control, kR, 2.0);
    ASSERT_EQ(c.controlPointIndex.size(), control.size());
    EXPECT_EQ(c.controlPointIndex.front(), 0);
    EXPECT_EQ(c.controlPointIndex.back(), static_cast<int>(c.points.size()) - 1);
    for (size_t k = 0; k < control.size(); ++k) {
        const glm::dvec3 p = c.points[c.controlPointIndex[k]];
        EXPECT_LT(kR * angle(p, common::unitFromLatLon(control[k].x, control[k].y)), 1e-9) << k;
    }
}

TEST(CurtainGeometry, SpacingArclengthAndNormals)
{
    const double spacing = 3.0;
    CurtainPolyline c = sampleCurtain(wavyCurtain(), kR, spacing);
    ASSERT_EQ(c.points.size(), c.arclengthKm.size());
    ASSERT_EQ(c.points.size(), c.normals.size());
    EXPECT_EQ(c.arclengthKm.front(), 0.0);
    for (size_t k = 0; k < c.points.size(); ++k) {
        EXPECT_NEAR(glm::length(c.points[k]), 1.0, 1e-14);
        EXPECT_NEAR(glm::length(c.normals[k]), 1.0, 1e-14);
        EXPECT_NEAR(glm::dot(c.normals[k], c.points[k]), 0.0, 1e-14);
        if (k == 0)
            continue;
        const double chord = kR * angle(c.points[k - 1], c.points[k]);
        const double step = c.arclengthKm[k] - c.arclengthKm[k - 1];
        EXPECT_LE(step, spacing * (1.0 + 1e-12)) << k;
        EXPECT_LE(chord, step * (1.0 + 1e-9)) << k; // an arc is no shorter than its great-circle chord
        EXPECT_GT(chord, 0.5 * step) << k;         // and no cusp doubles back within a step
    }
    const double reference = referenceLength(wavyCurtain());
    EXPECT_NEAR(c.arclengthKm.back() / reference, 1.0, 1e-6);
}

TEST(CurtainGeometry, NormalIsPerpendicularToTravel)
{
    // Central differences of a 50 m sampling approximate the tangent to O(h·curvature) ≈ 1e-3.
    CurtainPolyline c = sampleCurtain(wavyCurtain(), kR, 0.05);
    for (size_t k = 1; k + 1 < c.points.size(); ++k) {
        const glm::dvec3 travel = glm::normalize(c.points[k + 1] - c.points[k - 1]);
        ASSERT_LT(std::abs(glm::dot(travel, c.normals[k])), 2e-3) << k;
    }
}

TEST(CurtainGeometry, ArclengthAtControlPointsMatchesFineReference)
{
    CurtainPolyline coarse = sampleCurtain(wavyCurtain(), kR, 10.0);
    CurtainPolyline fine = sampleCurtain(wavyCurtain(), kR, 0.01);
    double chordSum = 0.0;
    size_t next = 1;
    for (size_t k = 1; k < fine.points.size() && next < coarse.controlPointIndex.size(); ++k) {
        chordSum += kR * angle(fine.points[k - 1], fine.points[k]);
        if (static_cast<int>(k) == fine.controlPointIndex[next]) {
            EXPECT_NEAR(coarse.arclengthKm[coarse.controlPointIndex[next]] / chordSum, 1.0, 1e-6) << next;
            ++next;
        }
    }
    EXPECT_EQ(next, coarse.controlPointIndex.size());
}

TEST(CurtainGeometry, GreatCircleInputStaysOnTheGreatCircle)
{
    // Uneven points on the great circle through (60° N, 10° W) and (70° N, 40° E).
    const glm::dvec3 a = common::unitFromLatLon(60.0, -10.0), b = common::unitFromLatLon(70.0, 40.0);
    const glm::dvec3 pole = glm::normalize(glm::cross(a, b));
    const glm::dvec3 along = glm::cross(pole, a);
    std::vector<glm::dvec2> control;
    for (double t : {0.0, 0.01, 0.05, 0.3, 0.31, 0.5})
        control.push_back(latLonFromUnit(std::cos(t) * a + std::sin(t) * along));
    CurtainPolyline c = sampleCurtain(control, kR, 5.0);
    for (size_t k = 0; k < c.points.size(); ++k) {
        EXPECT_LT(std::abs(glm::dot(c.points[k], pole)), 1e-12) << k;
        EXPECT_NEAR(glm::dot(c.normals[k], pole), 1.0, 1e-12) << k; // left of travel is the circle's pole
        EXPECT_NEAR(c.arclengthKm[k], kR * angle(c.points[0], c.points[k]), 1e-9) << k;
    }
    EXPECT_NEAR(c.arclengthKm.back(), kR * 0.5, 1e-9);
}

TEST(CurtainGeometry, NormalPointsLeftOfTravel)
{
    // Eastward along 65° N: left is north.
    CurtainPolyline c = sampleCurtain({{65.0, 0.0}, {65.0, 5.0}, {65.0, 10.0}}, kR, 5.0);
    for (size_t k = 0; k < c.points.size(); ++k) {
        const glm::dvec2 ll = latLonFromUnit(c.points[k]);
        const glm::dvec3 north = common::unitFromLatLon(ll.x + 1e-3, ll.y) - c.points[k];
        EXPECT_GT(glm::dot(c.normals[k], glm::normalize(north)), 0.99) << k;
    }
}

TEST(CurtainGeometry, LongitudeWrap)
{
    const std::vector<glm::dvec2> across = {{66.0, 178.0}, {66.5, 179.0}, {66.2, -179.0}, {67.0, -176.5}};
    std::vector<glm::dvec2> shifted = across; // the same curve rotated 10° west about the pole
    for (glm::dvec2& p : shifted)
        p.y = p.y > 0.0 ? p.y - 10.0 : p.y + 350.0;
    CurtainPolyline c = sampleCurtain(across, kR, 2.0);
    CurtainPolyline s = sampleCurtain(shifted, kR, 2.0);
    ASSERT_EQ(c.points.size(), s.points.size());
    EXPECT_NEAR(c.arclengthKm.back(), s.arclengthKm.back(), 1e-9);
    EXPECT_LT(c.arclengthKm.back(), 400.0); // the short way across the date line (the long way is > 14000 km)
    for (size_t k = 1; k < c.points.size(); ++k)
        EXPECT_LE(kR * angle(c.points[k - 1], c.points[k]), 2.0 * (1.0 + 1e-12));
}

TEST(CurtainGeometry, RejectsBadInput)
{
    EXPECT_THROW(sampleCurtain({{65.0, 0.0}}, kR, 1.0), std::invalid_argument);
    EXPECT_THROW(sampleCurtain({{65.0, 0.0}, {65.0, 0.0}}, kR, 1.0), std::invalid_argument);
    EXPECT_THROW(sampleCurtain({{0.0, 0.0}, {0.0, 95.0}}, kR, 1.0), std::invalid_argument);
    EXPECT_THROW(sampleCurtain({{65.0, 0.0}, {65.0, 1.0}}, kR, 0.0), std::invalid_argument);
}

TEST(CurtainGeometry, KeyframeInterpolationOnTheSphere)
{
    const std::vector<glm::dvec2> a = {{65.0, 179.0}, {60.0, 10.0}};
    const std::vector<glm::dvec2> b = {{67.0, -179.0}, {62.0, 20.0}};
    for (double w : {0.0, 0.25, 0.5, 1.0}) {
        std::vector<glm::dvec2> p = interpolateControlPoints(a, b, w);
        ASSERT_EQ(p.size(), a.size());
        for (size_t k = 0; k < a.size(); ++k) {
            const glm::dvec3 pa = common::unitFromLatLon(a[k].x, a[k].y), pb = common::unitFromLatLon(b[k].x, b[k].y);
            const glm::dvec3 pw = common::unitFromLatLon(p[k].x, p[k].y);
            EXPECT_NEAR(angle(pa, pw), w * angle(pa, pb), 1e-12);
            EXPECT_NEAR(angle(pw, pb), (1.0 - w) * angle(pa, pb), 1e-12);
        }
    }
    // Across the date line at equal latitudes the midpoint is at ±180°, not near 0°.
    const glm::dvec2 mid = interpolateControlPoints({{65.0, 179.0}}, {{65.0, -179.0}}, 0.5)[0];
    EXPECT_NEAR(std::abs(mid.y), 180.0, 1e-9);
    EXPECT_GT(mid.x, 65.0); // a great circle bulges poleward of the parallel
    EXPECT_THROW(interpolateControlPoints(a, {{0.0, 0.0}}, 0.5), std::invalid_argument);
    EXPECT_THROW(interpolateControlPoints({{0.0, 0.0}}, {{0.0, 180.0}}, 0.5), std::invalid_argument);
}

TEST(CurtainGeometry, SmoothWeightIsC1Ease)
{
    EXPECT_EQ(smoothWeight(-1.0, 2.0, 4.0), 0.0);
    EXPECT_EQ(smoothWeight(2.0, 2.0, 4.0), 0.0);
    EXPECT_EQ(smoothWeight(3.0, 2.0, 4.0), 0.5);
    EXPECT_EQ(smoothWeight(4.0, 2.0, 4.0), 1.0);
    EXPECT_EQ(smoothWeight(9.0, 2.0, 4.0), 1.0);
    const double e = 1e-6; // zero slope at both ends
    EXPECT_LT(smoothWeight(2.0 + e, 2.0, 4.0) / e, 1e-5);
    EXPECT_LT((1.0 - smoothWeight(4.0 - e, 2.0, 4.0)) / e, 1e-5);
    for (double t = 2.0; t < 4.0; t += 0.01)
        EXPECT_LE(smoothWeight(t, 2.0, 4.0), smoothWeight(t + 0.01, 2.0, 4.0));
}

} // namespace
} // namespace aurorawall::components::aurora::physics
