#include "components/aurora/physics/footprint_map.h"
#include "physics/constants.h"
#include "common/glsl.h"

#include "random_curtains.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <random>
#include <stdexcept>

// Named (not anonymous) namespaces, so the functions this file does not call raise no warnings.
namespace aurorawall::components::aurora::physics::footprint_tests_f64 {
AURORAWALL_GLSL_PRECISION(double)
#include "render/angle.glsl"
#include "components/aurora/footprint_map.glsl"
} // namespace aurorawall::components::aurora::physics::footprint_tests_f64
namespace aurorawall::components::aurora::physics::footprint_tests_f32 {
AURORAWALL_GLSL_PRECISION(float)
#include "render/angle.glsl"
#include "components/aurora/footprint_map.glsl"
} // namespace aurorawall::components::aurora::physics::footprint_tests_f32

namespace aurorawall::components::aurora::physics {
namespace {

namespace f64 = footprint_tests_f64;
namespace f32 = footprint_tests_f32;

using random_curtains::angle;
using random_curtains::kR;
using random_curtains::randomCurtains;
using random_curtains::randomInCap;

// The default map but `size` texels on a side.
FootprintMapSpec mapSpec(int size)
{
    FootprintMapSpec spec;
    spec.size = size;
    return spec;
}

// Great-circle distance in km from direction p to the polyline of great-circle arcs: the perpendicular
// distance R asin|p·n| where p projects inside the arc (n = a × b normalized), else the nearer end.
double distanceToArcKm(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b)
{
    const glm::dvec3 n = glm::normalize(glm::cross(a, b));
    if (glm::dot(glm::cross(a, p), n) >= 0.0 && glm::dot(glm::cross(p, b), n) >= 0.0)
        return kR * std::asin(std::min(1.0, std::abs(glm::dot(p, n))));
    return kR * std::min(angle(p, a), angle(p, b));
}

struct Nearest {
    double distanceKm;  // to the nearest polyline
    int curtain, point; // the nearest dense point
};

// Brute force: the nearest dense point, then the arcs that could be nearer than it: an arc point at angle x
// from p has an end within x + half the arc, so arcs with both ends beyond the nearest seed's angle plus half
// the longest arc are skipped.
Nearest bruteForce(const std::vector<CurtainPolyline>& curtains, const glm::dvec3& p)
{
    Nearest best{1e30, -1, -1};
    double bestDot = -2.0, longestArc = 0.0;
    for (size_t c = 0; c < curtains.size(); ++c)
        for (size_t k = 0; k < curtains[c].points.size(); ++k) {
            const double d = glm::dot(p, curtains[c].points[k]);
            if (d > bestDot) {
                bestDot = d;
                best.curtain = static_cast<int>(c);
                best.point = static_cast<int>(k);
            }
            if (k > 0)
                longestArc = std::max(longestArc, curtains[c].arclengthKm[k] - curtains[c].arclengthKm[k - 1]);
        }
    const double seedAngle = angle(p, curtains[best.curtain].points[best.point]);
    best.distanceKm = kR * seedAngle;
    const double reach = std::cos(std::min(aurorawall::physics::kPi, seedAngle + 0.5 * longestArc / kR)) - 1e-12;
    for (const CurtainPolyline& c : curtains)
        for (size_t k = 1; k < c.points.size(); ++k)
            if (std::max(glm::dot(p, c.points[k - 1]), glm::dot(p, c.points[k])) >= reach)
                best.distanceKm = std::min(best.distanceKm, distanceToArcKm(p, c.points[k - 1], c.points[k]));
    return best;
}

TEST(FootprintMap, ProjectionRoundTripDouble)
{
    FootprintMapSpec spec;
    spec.centreLatitudeDeg = 67.0;
    spec.centreLongitudeDeg = -150.0;
    spec.angularRadiusDeg = 60.0;
    const FootprintMap map = buildFootprintMap({}, spec, kR);
    std::mt19937_64 rng(1);
    double worstAngle = 0.0, worstCoord = 0.0;
    for (int k = 0; k < 20000; ++k) {
        const double maxAngle = k % 2 ? aurorawall::physics::kPi / 2 : 1e-6; // also very near the centre
        const glm::dvec3 d = randomInCap(rng, map.centre, map.east, maxAngle);
        const glm::dvec2 coord = f64::footprintMapCoord(d, map.centre, map.east, map.angularRadius);
        const glm::dvec3 back = f64::footprintMapDirection(coord, map.centre, map.east, map.angularRadius);
        worstAngle = std::max(worstAngle, angle(d, back));
        const glm::dvec2 again = f64::footprintMapCoord(back, map.centre, map.east, map.angularRadius);
        worstCoord = std::max(worstCoord, glm::length(again - coord));
        // Equidistant: the distance from the map centre is θ/(2Θ).
        EXPECT_NEAR(glm::length(coord - glm::dvec2(0.5)), angle(d, map.centre) / (2.0 * map.angularRadius), 1e-13);
    }
    EXPECT_LT(worstAngle, 1e-12);
    EXPECT_LT(worstCoord, 1e-12);
    const glm::dvec2 centre = f64::footprintMapCoord(map.centre, map.centre, map.east, map.angularRadius);
    EXPECT_EQ(centre, glm::dvec2(0.5));
}

TEST(FootprintMap, ProjectionFloatMatchesDouble)
{
    const FootprintMap map = buildFootprintMap({}, FootprintMapSpec{}, kR);
    const glm::vec3 centre(map.centre), east(map.east);
    const float radius = static_cast<float>(map.angularRadius);
    std::mt19937_64 rng(2);
    double worstCoord = 0.0, worstAngle = 0.0;
    for (int k = 0; k < 20000; ++k) {
        const glm::dvec3 d = randomInCap(rng, map.centre, map.east, k % 2 ? map.angularRadius : 1e-4);
        const glm::dvec2 exact = f64::footprintMapCoord(d, map.centre, map.east, map.angularRadius);
        const glm::vec2 coord = f32::footprintMapCoord(glm::vec3(d), centre, east, radius);
        worstCoord = std::max(worstCoord, glm::length(glm::dvec2(coord) - exact) * 2.0 * map.angularRadius);
        const glm::vec3 back = f32::footprintMapDirection(glm::vec2(exact), centre, east, radius);
        worstAngle = std::max(worstAngle, angle(glm::normalize(glm::dvec3(back)), d));
    }
    EXPECT_LT(worstCoord, 1e-6); // radians on the sphere; within the margin's float term
    EXPECT_LT(worstAngle, 1e-6);
}

TEST(FootprintMap, DefaultFrameLooksDownOnTheNorthPole)
{
    const FootprintMap map = buildFootprintMap({}, FootprintMapSpec{}, kR);
    EXPECT_LT(glm::length(map.centre - glm::dvec3(0, 0, 1)), 1e-16);
    const glm::dvec2 greenwich = f64::footprintMapCoord(common::unitFromLatLon(80.0, 0.0), map.centre, map.east, map.angularRadius);
    const glm::dvec2 east90 = f64::footprintMapCoord(common::unitFromLatLon(80.0, 90.0), map.centre, map.east, map.angularRadius);
    EXPECT_NEAR(greenwich.x, 0.5, 1e-15);
    EXPECT_NEAR(greenwich.y, 0.5 - 10.0 / 80.0, 1e-12); // longitude 0 straight down
    EXPECT_NEAR(east90.x, 0.5 + 10.0 / 80.0, 1e-12);    // 90° E to the right
    EXPECT_NEAR(east90.y, 0.5, 1e-15);
    // The map's right and top edges belong to the last texel.
    EXPECT_EQ(f64::footprintMapTexel(glm::dvec2(1.0, 0.0), 512.0), glm::dvec2(511.0, 0.0));
    EXPECT_EQ(f64::footprintMapTexel(glm::dvec2(0.5, 0.99999), 512.0), glm::dvec2(256.0, 511.0));
}

TEST(FootprintMap, TexelsHoldExactIntegers)
{
    std::mt19937_64 rng(3);
    const std::vector<CurtainPolyline> curtains = randomCurtains(rng, 4, 800.0, 5.0);
    const FootprintMap map = buildFootprintMap(curtains, mapSpec(64), kR);
    ASSERT_EQ(map.texels.size(), 64u * 64u * 4u);
    for (size_t t = 0; t < map.texels.size(); t += 4) {
        const float id = map.texels[t], index = map.texels[t + 1];
        ASSERT_EQ(id, std::floor(id));
        ASSERT_EQ(index, std::floor(index));
        ASSERT_GE(id, 0.0f);
        ASSERT_LT(id, 4.0f);
        ASSERT_LT(index, static_cast<float>(curtains[static_cast<size_t>(id)].points.size()));
        ASSERT_GE(map.texels[t + 2], 0.0f);
        // The nearest point of another curtain, packed as curtain * stride + point (-1: none looked
        // for here, or none near).
        const float packed = map.texels[t + 3];
        ASSERT_EQ(packed, std::floor(packed));
        if (packed < 0.0f) {
            ASSERT_EQ(packed, -1.0f);
            continue;
        }
        const int secondCurtain = static_cast<int>(packed) / kSecondPointStride;
        const int secondPoint = static_cast<int>(packed) % kSecondPointStride;
        ASSERT_NE(secondCurtain, static_cast<int>(id));
        ASSERT_LT(secondCurtain, 4);
        ASSERT_LT(secondPoint, static_cast<int>(curtains[static_cast<size_t>(secondCurtain)].points.size()));
    }
}

// The second channel against brute force: at every texel centre in the cap whose nearest curtain is
// within the band, the stored point of another curtain is the nearest point of any curtain but the
// first's, if that is within the band too; none is stored otherwise.
TEST(FootprintMap, SecondCurtainAgainstBruteForce)
{
    std::mt19937_64 rng(5);
    const std::vector<CurtainPolyline> curtains = randomCurtains(rng, 6, 1000.0, 5.0);
    FootprintMapSpec spec = mapSpec(128);
    spec.reachKm = 200.0;
    const FootprintMap map = buildFootprintMap(curtains, spec, kR);
    int texels = 0, withSecond = 0;
    for (int j = 0; j < spec.size; ++j)
        for (int i = 0; i < spec.size; ++i) {
            const glm::dvec3 here = footprintTexelDirection(map, i, j);
            if (f64::angleBetween(here, map.centre) > map.angularRadius)
                continue;
            const float* texel = &map.texels[4 * (size_t(j) * spec.size + i)];
            if (texel[2] > spec.reachKm)
                continue;
            const int first = static_cast<int>(texel[0]);
            double bestDot = -2.0;
            int bestCurtain = -1, bestPoint = -1;
            for (size_t c = 0; c < curtains.size(); ++c)
                if (static_cast<int>(c) != first)
                    for (size_t k = 0; k < curtains[c].points.size(); ++k)
                        if (glm::dot(here, curtains[c].points[k]) > bestDot) {
                            bestDot = glm::dot(here, curtains[c].points[k]);
                            bestCurtain = static_cast<int>(c);
                            bestPoint = static_cast<int>(k);
                        }
            ++texels;
            if (kR * std::acos(std::min(bestDot, 1.0)) > map.exactWithinKm) {
                EXPECT_EQ(texel[3], -1.0f) << i << "," << j;
                continue;
            }
            ++withSecond;
            EXPECT_EQ(texel[3], static_cast<float>(bestCurtain * kSecondPointStride + bestPoint)) << i << "," << j;
        }
    std::printf("second curtain: %d texels in the band, %d with another curtain that near\n", texels, withSecond);
    EXPECT_GT(withSecond, 100);
}

// Every texel centre that touches the cap against the brute-force nearest seed: in the band the stored
// seed is the nearest one and the distance its distance rounded down; outside, the stored distance is a
// lower bound of the distance to every seed and at least exactWithinKm. At N ≤ kCoarseMapSize the far
// texels hold JFA's distance less kJfaErrorTexels texels, so this also tests that allowance.
TEST(FootprintMap, BandIsExactAndFarTexelsAreLowerBounds)
{
    std::mt19937_64 rng(4);
    for (int size : {64, 128, 256, 512}) {
        FootprintMapSpec spec = mapSpec(size);
        spec.reachKm = 20.0;
        long bandTexels = 0, farTexels = 0;
        double farSlackTexels = 0.0, tightestTexels = 1e30;
        for (int trial = 0; trial < (size >= 512 ? 1 : 4); ++trial) {
            const std::vector<CurtainPolyline> curtains = randomCurtains(rng, 10, 1000.0, size >= 256 ? 10.0 : 5.0);
            const FootprintMap map = buildFootprintMap(curtains, spec, kR);
            const double h = kR * 2.0 * map.angularRadius / size;
            for (int j = 0; j < size; ++j)
                for (int i = 0; i < size; ++i) {
                    const glm::dvec3 d = footprintTexelDirection(map, i, j);
                    if (angle(d, map.centre) > map.angularRadius + std::sqrt(0.5) * h / kR)
                        continue; // never read: beyond the cap by more than half a texel diagonal
                    double bestDot = -2.0;
                    int curtain = -1, point = -1;
                    for (size_t c = 0; c < curtains.size(); ++c)
                        for (size_t k = 0; k < curtains[c].points.size(); ++k)
                            if (glm::dot(d, curtains[c].points[k]) > bestDot) {
                                bestDot = glm::dot(d, curtains[c].points[k]);
                                curtain = static_cast<int>(c);
                                point = static_cast<int>(k);
                            }
                    const float* texel = &map.texels[4 * (static_cast<size_t>(j) * size + i)];
                    const double trueKm = kR * angle(d, curtains[curtain].points[point]);
                    if (trueKm <= map.exactWithinKm * (1.0 - 1e-12)) {
                        ++bandTexels;
                        ASSERT_EQ(texel[0], curtain) << "N=" << size << " texel " << i << "," << j;
                        ASSERT_EQ(texel[1], point) << "N=" << size << " texel " << i << "," << j;
                        ASSERT_LE(texel[2], trueKm);
                        ASSERT_GE(texel[2], std::nextafter(static_cast<float>(trueKm), 0.0f));
                    } else if (trueKm > map.exactWithinKm * (1.0 + 1e-12)) {
                        ++farTexels;
                        ASSERT_LE(texel[2], trueKm) << "N=" << size << " texel " << i << "," << j;
                        ASSERT_GE(texel[2], std::nextafter(static_cast<float>(map.exactWithinKm), 0.0f));
                        ASSERT_EQ(texel[3], -1.0f);
                        farSlackTexels += (trueKm - texel[2]) / h;
                        if (texel[2] > map.exactWithinKm)
                            tightestTexels = std::min(tightestTexels, (trueKm - texel[2]) / h);
                    }
                }
        }
        std::printf("N=%d: %ld band texels exact; %ld far texels, true minus stored distance mean %.2f texels, "
                    "smallest %.3f texels where above the band\n",
                    size, bandTexels, farTexels, farSlackTexels / farTexels, tightestTexels);
        EXPECT_GT(bandTexels, 100);
        EXPECT_GT(farTexels, 100);
    }
}

// For random points in the cap (half anywhere, half within 40 km of a curtain), the lookup's conservative
// distance never exceeds the true distance to the nearest curtain polyline.
TEST(FootprintMap, ConservativeDistanceIsALowerBound)
{
    std::mt19937_64 rng(5);
    std::normal_distribution<double> normal(0.0, 1.0);
    const double spacing = 5.0;
    const std::vector<CurtainPolyline> curtains = randomCurtains(rng, 10, 1000.0, spacing);
    const FootprintMapSpec spec;
    const glm::dvec3 pole(0, 0, 1), east(0, -1, 0);
    const double cap = spec.angularRadiusDeg * aurorawall::physics::kPi / 180.0;
    std::vector<glm::dvec3> points;
    std::vector<Nearest> truth;
    const int count = 100000;
    for (int k = 0; k < count; ++k) {
        glm::dvec3 p = randomInCap(rng, pole, east, cap);
        if (k % 2) {
            const CurtainPolyline& c = curtains[rng() % curtains.size()];
            const glm::dvec3 offset(normal(rng), normal(rng), normal(rng));
            p = glm::normalize(c.points[rng() % c.points.size()] + offset * (20.0 / kR));
        }
        if (angle(p, pole) > cap)
            continue;
        points.push_back(p);
        truth.push_back(bruteForce(curtains, p));
    }
    ASSERT_GT(points.size(), 99000u);
    for (int size : {64, 128, 256, 512, 1024}) {
        FootprintMapSpec s = spec;
        s.size = size;
        const FootprintMap map = buildFootprintMap(curtains, s, kR);
        double tightest = 1e30, nearSlack = 0.0;
        int nearCount = 0, maxIndexOffset = 0, otherCurtain = 0;
        for (size_t k = 0; k < points.size(); ++k) {
            const FootprintSample sample = map.lookup(points[k]);
            ASSERT_LE(sample.conservativeKm, truth[k].distanceKm) << "N=" << size << " point " << k;
            if (sample.conservativeKm > 0.0)
                tightest = std::min(tightest, truth[k].distanceKm - sample.conservativeKm);
            if (truth[k].distanceKm < 20.0) {
                nearSlack += truth[k].distanceKm - sample.conservativeKm;
                ++nearCount;
                if (sample.curtainId == truth[k].curtain)
                    maxIndexOffset = std::max(maxIndexOffset, std::abs(sample.pointIndex - truth[k].point));
                else
                    ++otherCurtain;
            }
        }
        std::printf("N=%d: margin %.2f km; true minus conservative distance: smallest %.3f km (where positive), "
                    "mean %.2f km within 20 km of a curtain; there the stored point is up to %d points (%.0f km) "
                    "from the nearest, on another curtain for %d of %d points\n",
                    size, map.marginKm, tightest, nearSlack / nearCount, maxIndexOffset, maxIndexOffset * spacing,
                    otherCurtain, nearCount);
    }
}

TEST(FootprintMap, BuildIsDeterministic)
{
    std::mt19937_64 rng(6);
    const std::vector<CurtainPolyline> curtains = randomCurtains(rng, 10, 1000.0, 2.0);
    const FootprintMap a = buildFootprintMap(curtains, mapSpec(256), kR);
    const FootprintMap b = buildFootprintMap(curtains, mapSpec(256), kR);
    ASSERT_EQ(a.texels.size(), b.texels.size());
    EXPECT_EQ(std::memcmp(a.texels.data(), b.texels.data(), a.texels.size() * sizeof(float)), 0);
    EXPECT_EQ(a.marginKm, b.marginKm);
}

TEST(FootprintMap, FarAndEmpty)
{
    std::mt19937_64 rng(7);
    const std::vector<CurtainPolyline> curtains = randomCurtains(rng, 3, 500.0, 5.0);
    const FootprintMapSpec spec = mapSpec(128);
    const FootprintMap map = buildFootprintMap(curtains, spec, kR);
    for (int k = 0; k < 1000; ++k) {
        const glm::dvec3 p = randomInCap(rng, map.centre, map.east, aurorawall::physics::kPi);
        const double theta = angle(p, map.centre);
        if (theta <= map.angularRadius)
            continue;
        const FootprintSample sample = map.lookup(p);
        EXPECT_EQ(sample.curtainId, -1);
        EXPECT_NEAR(sample.conservativeKm, kR * (theta - map.angularRadius), 1e-9);
        EXPECT_LE(sample.conservativeKm, bruteForce(curtains, p).distanceKm);
    }
    const FootprintMap empty = buildFootprintMap({}, spec, kR);
    for (size_t t = 0; t < empty.texels.size(); t += 4) {
        ASSERT_EQ(empty.texels[t], -1.0f);
        ASSERT_EQ(empty.texels[t + 1], -1.0f);
        ASSERT_LE(empty.texels[t + 2], aurorawall::physics::kPi * kR);
        ASSERT_GT(empty.texels[t + 2], aurorawall::physics::kPi * kR - 1e-3);
    }
    EXPECT_EQ(empty.lookup(map.centre).curtainId, -1);

    FootprintMapSpec small = spec;
    small.angularRadiusDeg = 5.0; // the curtains reach beyond 5° from the pole
    EXPECT_THROW(buildFootprintMap(curtains, small, kR), std::invalid_argument);
    FootprintMapSpec odd = spec;
    odd.size = 100;
    EXPECT_THROW(buildFootprintMap(curtains, odd, kR), std::invalid_argument);
}

} // namespace
} // namespace aurorawall::components::aurora::physics
