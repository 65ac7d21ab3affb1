// Views drawn at random for the accuracy runs: the same seed gives the same views, each kind keeps
// its camera in its altitude range and near the scene camera, the camera frame stays orthonormal and
// right-handed, and the times stay in their ranges.
#include "accuracy/random_views.h"

#include <gtest/gtest.h>

#include "physics/constants.h"

#include <algorithm>
#include <cmath>

using namespace aurorawall;

namespace {

constexpr double kRadiusKm = 6371.0;
constexpr double kStartS = 180.0;

accuracy::SceneView sceneStart()
{
    accuracy::SceneView view;
    view.frame.timeS = kStartS;
    view.frame.cameraPositionKm = glm::normalize(glm::dvec3(-0.467, -0.224, 0.868)) * (kRadiusKm + 70.0);
    view.frame.zoom = 1.5;
    view.frame.exposure = 300.0;
    return view;
}

double angleDeg(glm::dvec3 a, glm::dvec3 b)
{
    return std::acos(std::clamp(glm::dot(glm::normalize(a), glm::normalize(b)), -1.0, 1.0)) * 180.0 / physics::kPi;
}

TEST(RandomViews, TheSameSeedGivesTheSameViews)
{
    accuracy::RandomViews a(7, {kRadiusKm}), b(7, {kRadiusKm}), c(8, {kRadiusKm});
    for (int k = 0; k < 8; ++k) {
        const auto kind = accuracy::ViewKind(k % accuracy::kViewKinds);
        const accuracy::SceneView va = a.draw(sceneStart(), kind), vb = b.draw(sceneStart(), kind),
                                  vc = c.draw(sceneStart(), kind);
        EXPECT_EQ(va.frame.cameraPositionKm, vb.frame.cameraPositionKm);
        EXPECT_EQ(va.frame.cameraBack, vb.frame.cameraBack);
        EXPECT_EQ(va.frame.cameraUp, vb.frame.cameraUp);
        EXPECT_EQ(va.frame.timeS, vb.frame.timeS);
        EXPECT_NE(va.frame.cameraPositionKm, vc.frame.cameraPositionKm);
    }
}

TEST(RandomViews, EachKindKeepsItsRangesAndAnOrthonormalFrame)
{
    struct Range {
        double lowKm, highKm, siteDeg;
    };
    const Range ranges[accuracy::kViewKinds] = {{0.01, 3.0, 8.0}, {90.0, 250.0, 8.0}, {250.0, 1500.0, 8.0},
                                                {2000.0, 40000.0, 40.0}};
    accuracy::RandomViews views(1, {kRadiusKm});
    const accuracy::SceneView start = sceneStart();
    int hugeTimes = 0;
    const int draws = 400;
    for (int k = 0; k < draws; ++k) {
        const auto kind = accuracy::ViewKind(k % accuracy::kViewKinds);
        const Range& r = ranges[int(kind)];
        const accuracy::SceneView v = views.draw(start, kind);
        const cluster::FrameState& f = v.frame;
        const double altitudeKm = glm::length(f.cameraPositionKm) - kRadiusKm;
        EXPECT_GE(altitudeKm, r.lowKm - 1e-9) << accuracy::viewKindName(kind);
        EXPECT_LE(altitudeKm, r.highKm + 1e-9) << accuracy::viewKindName(kind);
        EXPECT_LE(angleDeg(f.cameraPositionKm, start.frame.cameraPositionKm), r.siteDeg + 1e-9);
        for (const glm::dvec3& axis : {f.cameraRight, f.cameraUp, f.cameraBack})
            EXPECT_NEAR(glm::length(axis), 1.0, 1e-12);
        EXPECT_NEAR(glm::dot(f.cameraRight, f.cameraUp), 0.0, 1e-12);
        EXPECT_NEAR(glm::dot(f.cameraUp, f.cameraBack), 0.0, 1e-12);
        EXPECT_NEAR(glm::dot(f.cameraBack, f.cameraRight), 0.0, 1e-12);
        EXPECT_NEAR(glm::dot(glm::cross(f.cameraRight, f.cameraUp), f.cameraBack), 1.0, 1e-12); // right-handed
        const double t = f.timeS - kStartS;
        const bool huge = t >= 1e4;
        hugeTimes += huge;
        EXPECT_TRUE((t >= 0.0 && t < 600.0) || (huge && t < 1e8)) << t;
        EXPECT_TRUE(std::isnan(f.nextTimeS));
        if (kind == accuracy::ViewKind::Space)
            EXPECT_GE(f.zoom, start.frame.zoom * (r.lowKm - 250.0) / 1000.0); // zoomed to ~1,000 km of the layer
        else
            EXPECT_EQ(f.zoom, start.frame.zoom);
        EXPECT_EQ(f.exposure, start.frame.exposure);
    }
    // A quarter of the times are huge: 100 expected, binomial standard deviation 8.7.
    EXPECT_GT(hugeTimes, 50);
    EXPECT_LT(hugeTimes, 150);
}

} // namespace
