#include "physics/colour.h"
#include "components/aurora/physics/emission.h"
#include "quadrature.h"

#include <gtest/gtest.h>

namespace aurorawall::components::aurora::physics {
namespace {

using testing::peakAltitude;

glm::dvec3 emissionRgb(double altitudeKm, double energyKeV)
{
    glm::dvec3 rgb(0.0);
    for (int k = 0; k < kLineCount; ++k) {
        auto line = static_cast<EmissionLine>(k);
        rgb += volumeEmissionRate(line, altitudeKm, energyKeV, Spectrum::Maxwellian) * lineLinearSrgbPerRayleigh(line);
    }
    return rgb;
}

TEST(Emission, QuenchingActsLowDown)
{
    EXPECT_GT(o1dRadiatingFraction(300.0), 0.5);
    EXPECT_LT(o1dRadiatingFraction(150.0), 0.05);
    EXPECT_GT(o1sRadiatingFraction(120.0), 0.95);
    EXPECT_LT(o1sRadiatingFraction(80.0), o1sRadiatingFraction(100.0));
    EXPECT_LT(oxygenTransferFraction(90.0), 0.2);
    EXPECT_GT(oxygenTransferFraction(120.0), 0.9);
}

TEST(Emission, GreenPeaksNear110To120KmForModerateElectrons)
{
    for (double e0 : {1.0, 1.5}) {
        double peak = peakAltitude(
            [&](double z) { return volumeEmissionRate(EmissionLine::Green5577, z, e0, Spectrum::Maxwellian); }, 80.0, 300.0);
        EXPECT_GT(peak, 108.0) << e0;
        EXPECT_LT(peak, 122.0) << e0;
    }
}

TEST(Emission, RedDominatesAbove230Km)
{
    for (double z : {230.0, 300.0, 400.0}) {
        glm::dvec3 rgb = emissionRgb(z, 2.0);
        EXPECT_GT(rgb.r, rgb.g) << z;
        EXPECT_GT(rgb.r, rgb.b) << z;
    }
    glm::dvec3 atPeak = emissionRgb(115.0, 2.0);
    EXPECT_GT(atPeak.g, atPeak.r);
    EXPECT_GT(atPeak.g, atPeak.b);
}

TEST(Emission, LowerBorderOfEnergeticAuroraIsMagenta)
{
    // 10 keV Maxwellian: below ~90 km green fades and red (N2 1PG) and blue (427.8) remain.
    glm::dvec3 border = emissionRgb(85.0, 10.0);
    EXPECT_GT(border.r, border.g);
    EXPECT_GT(border.b, border.g);
}

TEST(Emission, ColumnBrightnessPerErgIsOfTheLiteratureOrder)
{
    // Calibration points at 5 keV: 213 R of 427.8 nm (Rees & Luckey 1974) and 1 kR of 557.7 nm per
    // erg cm⁻² s⁻¹ (the yields' constants 0.4213 and 2.213 photons/keV); they must hold to the
    // constants' 4 digits, half a unit of the last: 213 · 0.00005/0.4213 = 0.025 R and
    // 1000 · 0.0005/2.213 = 0.23 R (measured 212.990 and 999.906; Simpson's rule over 9400 intervals
    // adds far less).
    EXPECT_NEAR(columnBrightnessRayleigh(EmissionLine::Blue4278, 5.0, Spectrum::Monoenergetic), 213.0,
                213.0 * 0.00005 / 0.4213);
    EXPECT_NEAR(columnBrightnessRayleigh(EmissionLine::Green5577, 5.0, Spectrum::Monoenergetic), 1000.0,
                1000.0 * 0.0005 / 2.213);
    // Elsewhere the model follows from the profile: 427.8 nm stays within 30% of 213 R over 1–10 keV
    // (Maxwellian: measured 185 R at 1 keV to 254 R at 10 keV).
    for (double e0 : {1.0, 2.0, 5.0, 10.0}) {
        double blue = columnBrightnessRayleigh(EmissionLine::Blue4278, e0, Spectrum::Maxwellian);
        EXPECT_GT(blue, 0.7 * 213.0) << e0;
        EXPECT_LT(blue, 1.3 * 213.0) << e0;
    }
}

} // namespace
} // namespace aurorawall::components::aurora::physics
