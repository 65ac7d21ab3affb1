#include "components/aurora/curtain_frames.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace aurorawall;

namespace {

components::aurora::Curtain twoKeyCurtain()
{
    components::aurora::Curtain c;
    components::aurora::CurtainKey a, b;
    a.timeS = 10.0;
    a.pointsLatLonDeg = {{65.0, 0.0}, {65.0, 10.0}};
    a.energyKeV = 2.0;
    a.energyFluxErgPerCm2S = 1.0;
    b = a;
    b.timeS = 20.0;
    b.pointsLatLonDeg = {{67.0, 0.0}, {67.0, 10.0}};
    b.energyKeV = 8.0;
    b.energyFluxErgPerCm2S = 3.0;
    b.detailPhase = 1.0;
    c.keys = {a, b};
    return c;
}

} // namespace

TEST(CurtainFrames, HoldsBeforeTheFirstAndAfterTheLastKey)
{
    const components::aurora::Curtain c = twoKeyCurtain();
    EXPECT_EQ(components::aurora::curtainAt(c, -1e9, 100.0).controlPointsLatLonDeg, c.keys[0].pointsLatLonDeg);
    EXPECT_DOUBLE_EQ(components::aurora::curtainAt(c, 10.0, 100.0).energyKeV, 2.0);
    EXPECT_DOUBLE_EQ(components::aurora::curtainAt(c, 20.0, 100.0).energyKeV, 8.0);
    EXPECT_DOUBLE_EQ(components::aurora::curtainAt(c, 1e9, 100.0).energyFluxErgPerCm2S, 3.0);
}

TEST(CurtainFrames, HalfwayIsTheEasedMidpoint)
{
    // smoothstep(1/2) = 1/2: energy is the geometric mean, flux and phase the arithmetic means,
    // points half way along their great circles (here along a meridian: latitude 66).
    const components::aurora::CurtainState s = components::aurora::curtainAt(twoKeyCurtain(), 15.0, 100.0);
    EXPECT_NEAR(s.energyKeV, 4.0, 1e-12);
    EXPECT_NEAR(s.energyFluxErgPerCm2S, 2.0, 1e-12);
    EXPECT_NEAR(s.detailPhase, 0.5, 1e-12);
    EXPECT_NEAR(s.controlPointsLatLonDeg[0].x, 66.0, 1e-9);
    EXPECT_NEAR(s.controlPointsLatLonDeg[0].y, 0.0, 1e-9);
}

TEST(CurtainFrames, DriftIsReducedModuloTheStripInDouble)
{
    components::aurora::Curtain c = twoKeyCurtain();
    c.driftKmPerS = 3.7;
    for (double t : {0.0, 12.5, 1e9, 1e9 + 0.25, -1e9}) {
        const double offset = components::aurora::curtainAt(c, t, 128.0).detailOffsetKm;
        EXPECT_GE(offset, 0.0);
        EXPECT_LT(offset, 128.0);
        // The same position on the periodic strip as the long double product (compared on the circle).
        const double exact = double(std::fmod((long double)3.7 * t, 128.0L));
        EXPECT_NEAR(std::remainder(offset - exact, 128.0), 0.0, 1e-6) << "t=" << t;
    }
}

TEST(CurtainFrames, PulsationDimsByItsDepth)
{
    components::aurora::Curtain c = twoKeyCurtain();
    c.pulsationPeriodS = 8.0;
    c.pulsationDepth = 0.75;
    // Full brightness at the start of a cycle, 1 - depth half a cycle later; also at t = 1e9 s.
    EXPECT_NEAR(components::aurora::curtainAt(c, 1e9, 1.0).energyFluxErgPerCm2S, 3.0, 1e-9);
    EXPECT_NEAR(components::aurora::curtainAt(c, 1e9 + 4.0, 1.0).energyFluxErgPerCm2S, 3.0 * 0.25, 1e-9);
}
