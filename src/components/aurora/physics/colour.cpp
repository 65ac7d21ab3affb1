#include "components/aurora/physics/colour.h"

#include "common/constants.h"

#include <algorithm>
#include <cmath>

namespace aurorawall::aurora {

glm::dvec3 xyzToLinearSrgb(glm::dvec3 xyz)
{
    return {3.2406 * xyz.x - 1.5372 * xyz.y - 0.4986 * xyz.z,
            -0.9689 * xyz.x + 1.8758 * xyz.y + 0.0415 * xyz.z,
            0.0557 * xyz.x - 0.2040 * xyz.y + 1.0570 * xyz.z};
}

double linearSrgbLuminance(glm::dvec3 rgb)
{
    return 0.2126 * rgb.r + 0.7152 * rgb.g + 0.0722 * rgb.b;
}

glm::dvec3 desaturateIntoGamut(glm::dvec3 rgb)
{
    double luminance = std::max(linearSrgbLuminance(rgb), 0.0);
    glm::dvec3 grey(luminance);
    double saturation = 1.0;
    for (int k = 0; k < 3; ++k) {
        if (rgb[k] < 0.0) saturation = std::min(saturation, luminance / (luminance - rgb[k]));
    }
    return grey + saturation * (rgb - grey);
}

double rayleighFromColumnRate(double photonsPerCm2PerS)
{
    return photonsPerCm2PerS / 1e6;
}

double radianceWattsPerM2Sr(double rayleigh, double wavelengthNm)
{
    constexpr double kPlanckTimesLight = 6.62607015e-34 * 299792458.0; // J m
    return rayleigh * 1e10 / (4.0 * kPi) * kPlanckTimesLight / (wavelengthNm * 1e-9);
}

glm::dvec3 lineLinearSrgbPerRayleigh(double wavelengthNm, glm::dvec3 cieXyz)
{
    constexpr double kLumensPerWatt = 683.0;
    const double radiance = radianceWattsPerM2Sr(1.0, wavelengthNm);
    return desaturateIntoGamut(xyzToLinearSrgb(cieXyz)) * (kLumensPerWatt * radiance);
}

glm::dvec3 lineLinearSrgbPerRayleigh(EmissionLine line)
{
    const LineInfo& info = lineInfo(line);
    return lineLinearSrgbPerRayleigh(info.wavelengthNm, info.cieXyz);
}

} // namespace aurorawall::aurora
