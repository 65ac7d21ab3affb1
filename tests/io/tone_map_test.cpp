#include "io/tone_map.h"

#include <gtest/gtest.h>

#include <glm/glm.hpp>

#include <cmath>
#include <limits>

using namespace aurorawall::io;

namespace {

const ToneMap aces{ToneMap::Curve::AcesFilmic, 1.0};
const ToneMap magnitude{ToneMap::Curve::MagnitudeGamma, 1.0};

} // namespace

TEST(ToneMap, SrgbTransferFunctionAtKnownPoints)
{
    EXPECT_EQ(srgbEncode(0.0), 0.0);
    EXPECT_DOUBLE_EQ(srgbEncode(0.0031308), 12.92 * 0.0031308); // 0.040449936, the breakpoint
    // The two pieces of IEC 61966-2-1 meet at the breakpoint (to the standard's 4 digits).
    EXPECT_NEAR(1.055 * std::pow(0.0031308, 1 / 2.4) - 0.055, srgbEncode(0.0031308), 1e-7);
    EXPECT_NEAR(srgbEncode(0.5), 0.735356983, 1e-9); // 1.055 * 0.5^(1/2.4) - 0.055
    EXPECT_DOUBLE_EQ(srgbEncode(1.0), 1.0);
}

TEST(ToneMap, AcesFilmicFitAtKnownPoints)
{
    EXPECT_EQ(acesFilmic(glm::dvec3(0.0)), glm::dvec3(0.0));
    EXPECT_DOUBLE_EQ(acesFilmic(glm::dvec3(1.0)).r, 2.54 / 3.16); // (2.51 + 0.03) / (2.43 + 0.59 + 0.14)
    EXPECT_DOUBLE_EQ(acesFilmic(glm::dvec3(1e6)).r, 1.0);           // saturates
}

TEST(ToneMap, AcesPixelIsTheFitFollowedBySrgb)
{
    const glm::dvec3 display = toneMapPixel(glm::dvec3(1.0, 0.5, 0.0), aces);
    EXPECT_DOUBLE_EQ(display.r, srgbEncode(2.54 / 3.16));
    EXPECT_DOUBLE_EQ(display.g, srgbEncode(0.5 * (2.51 * 0.5 + 0.03) / (0.5 * (2.43 * 0.5 + 0.59) + 0.14)));
    EXPECT_EQ(display.b, 0.0);
}

TEST(ToneMap, MagnitudeGammaKeepsTheColourDirection)
{
    const glm::dvec3 color(0.02, 0.05, 0.01);
    const glm::dvec3 display = toneMapPixel(color, magnitude);
    EXPECT_NEAR(glm::length(glm::normalize(display) - glm::normalize(color)), 0.0, 1e-12);
    EXPECT_NEAR(glm::length(display), std::pow(glm::length(color), 1 / 2.2), 1e-12);
    // A grey g maps to g (sqrt(3) g)^(1/2.2 - 1) per component, so white (1, 1, 1) shows as 0.741,
    // and (10, 10, 10) goes beyond 1 and clamps to white.
    EXPECT_DOUBLE_EQ(toneMapPixel(glm::dvec3(1.0), magnitude).g, std::pow(std::sqrt(3.0), 1 / 2.2 - 1));
    EXPECT_EQ(toneMapPixel(glm::dvec3(10.0), magnitude), glm::dvec3(1.0));
}

TEST(ToneMap, ZeroStaysZero)
{
    EXPECT_EQ(toneMapPixel(glm::dvec3(0.0), aces), glm::dvec3(0.0));
    EXPECT_EQ(toneMapPixel(glm::dvec3(0.0), magnitude), glm::dvec3(0.0));
    EXPECT_EQ(magnitudeGamma(glm::dvec3(0.0)), glm::dvec3(0.0));
}

TEST(ToneMap, ExposureScalesRadianceBeforeTheCurve)
{
    const glm::dvec3 radiance(0.1, 0.2, 0.3);
    for (ToneMap::Curve curve : {ToneMap::Curve::AcesFilmic, ToneMap::Curve::MagnitudeGamma}) {
        const glm::dvec3 a = toneMapPixel(radiance, ToneMap{curve, 2.0});
        const glm::dvec3 b = toneMapPixel(2.0 * radiance, ToneMap{curve, 1.0});
        EXPECT_NEAR(glm::length(a - b), 0.0, 1e-15);
    }
}

TEST(ToneMap, OutOfRangeInputsGiveValuesInZeroToOne)
{
    const double quietNan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    for (const ToneMap& toneMap : {aces, magnitude}) {
        // Negative (out of gamut) components count as 0: the ACES fit would map -1 to 1.25.
        EXPECT_EQ(toneMapPixel(glm::dvec3(-1.0, -5.0, 0.0), toneMap), glm::dvec3(0.0));
        EXPECT_EQ(toneMapPixel(glm::dvec3(quietNan, 0.0, 0.0), toneMap), glm::dvec3(0.0));
        // Infinite and huge values count as HALF_MAX, which both curves show as (nearly) white.
        for (const glm::dvec3 display : {toneMapPixel(glm::dvec3(inf), toneMap),
                                         toneMapPixel(glm::dvec3(1e30, 0.0, 0.0), toneMap)}) {
            EXPECT_LE(display.r, 1.0);
            EXPECT_NEAR(display.r, 1.0, 1e-4);
        }
    }
}
