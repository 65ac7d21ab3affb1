#include "physics/colour.h"
#include "physics/constants.h"

#include <gtest/gtest.h>

#include <cmath>

namespace aurorawall::physics {
namespace {

// CIE xy chromaticity of a linear sRGB colour (IEC 61966-2-1 linear sRGB → XYZ).
glm::dvec2 chromaticity(glm::dvec3 rgb)
{
    glm::dvec3 xyz(0.4124 * rgb.r + 0.3576 * rgb.g + 0.1805 * rgb.b, 0.2126 * rgb.r + 0.7152 * rgb.g + 0.0722 * rgb.b,
                   0.0193 * rgb.r + 0.1192 * rgb.g + 0.9505 * rgb.b);
    return glm::dvec2(xyz.x, xyz.y) / (xyz.x + xyz.y + xyz.z);
}

// Hue angle around the white point (1, 1, 1) in the xy chromaticity plane.
double hueAngle(glm::dvec3 rgb)
{
    glm::dvec2 d = chromaticity(rgb) - chromaticity(glm::dvec3(1.0));
    return std::atan2(d.y, d.x);
}

TEST(Colour, D65WhiteMapsToEqualRgb)
{
    glm::dvec3 white = xyzToLinearSrgb({0.9505, 1.0, 1.0890});
    EXPECT_NEAR(white.r, 1.0, 1e-3);
    EXPECT_NEAR(white.g, 1.0, 1e-3);
    EXPECT_NEAR(white.b, 1.0, 1e-3);
}

TEST(Colour, AllThreeLinesAreOutOfGamut)
{
    for (EmissionLine line : {EmissionLine::Blue4278, EmissionLine::Green5577, EmissionLine::Red6300}) {
        glm::dvec3 rgb = xyzToLinearSrgb(lineInfo(line).cieXyz);
        EXPECT_LT(std::min({rgb.r, rgb.g, rgb.b}), 0.0) << lineInfo(line).name;
    }
}

TEST(Colour, GamutMappingKeepsLuminanceAndHue)
{
    for (int k = 0; k < kLineCount; ++k) {
        const LineInfo& info = lineInfo(static_cast<EmissionLine>(k));
        glm::dvec3 rgb = xyzToLinearSrgb(info.cieXyz);
        glm::dvec3 mapped = desaturateIntoGamut(rgb);
        EXPECT_GE(std::min({mapped.r, mapped.g, mapped.b}), -1e-15) << info.name;
        EXPECT_NEAR(linearSrgbLuminance(mapped), linearSrgbLuminance(rgb), 1e-15) << info.name;
        EXPECT_NEAR(linearSrgbLuminance(mapped), info.cieXyz.y, 2e-3 * info.cieXyz.y + 1e-6) << info.name;
        EXPECT_NEAR(hueAngle(mapped), hueAngle(rgb), 1e-9) << info.name;
        // Some component lands exactly on 0: the least desaturation that fits.
        EXPECT_NEAR(std::min({mapped.r, mapped.g, mapped.b}), 0.0, 1e-15) << info.name;
    }
}

TEST(Colour, InGamutColoursAreUnchanged)
{
    glm::dvec3 rgb(0.2, 0.5, 0.9);
    glm::dvec3 mapped = desaturateIntoGamut(rgb);
    EXPECT_EQ(mapped, rgb);
}

TEST(Colour, LinesHaveTheirExpectedHues)
{
    glm::dvec3 green = lineLinearSrgbPerRayleigh(EmissionLine::Green5577);
    glm::dvec3 red = lineLinearSrgbPerRayleigh(EmissionLine::Red6300);
    glm::dvec3 blue = lineLinearSrgbPerRayleigh(EmissionLine::Blue4278);
    EXPECT_GT(green.g, green.r);
    EXPECT_GT(red.r, 5.0 * red.b);
    EXPECT_GT(blue.b, 2.0 * blue.r);
}

TEST(Colour, RayleighToRadiance)
{
    EXPECT_DOUBLE_EQ(rayleighFromColumnRate(1e6), 1.0);
    // 1 kR of 557.7 nm: 1e13/(4π) photons m⁻² s⁻¹ sr⁻¹ × 3.5618e-19 J = 2.8344e-7 W m⁻² sr⁻¹.
    EXPECT_NEAR(radianceWattsPerM2Sr(1000.0, 557.7) / 2.8344e-7, 1.0, 1e-4);
    // Its luminance: 683 · ȳ · radiance cd/m².
    glm::dvec3 green = lineLinearSrgbPerRayleigh(EmissionLine::Green5577) * 1000.0;
    EXPECT_NEAR(linearSrgbLuminance(green), kLumensPerWatt * 0.99862 * 2.8344e-7, 1e-3 * 1.93e-4);
}

} // namespace
} // namespace aurorawall::physics
