#include "physics/colour.h"

#include "physics/constants.h"
#include "common/glsl.h"

#include <algorithm>
#include <cmath>

namespace aurorawall::physics {

namespace f64 {
AURORAWALL_GLSL_PRECISION(double)
#include "physics/colour.glsl"
} // namespace f64

glm::dvec3 xyzToLinearSrgb(glm::dvec3 xyz) { return f64::xyzToLinearSrgb(xyz); }

double linearSrgbLuminance(glm::dvec3 rgb) { return f64::linearSrgbLuminance(rgb); }

glm::dvec3 desaturateIntoGamut(glm::dvec3 rgb) { return f64::desaturateIntoGamut(rgb); }

double rayleighFromColumnRate(double photonsPerCm2PerS)
{
    return photonsPerCm2PerS / 1e6;
}

double radianceWattsPerM2Sr(double rayleigh, double wavelengthNm)
{
    constexpr double kPlanckTimesLight = kPlanck * kSpeedOfLight; // J m
    return rayleigh * 1e10 / (4.0 * physics::kPi) * kPlanckTimesLight / (wavelengthNm * 1e-9);
}

glm::dvec3 lineLinearSrgbPerRayleigh(double wavelengthNm, glm::dvec3 cieXyz)
{
    const double radiance = radianceWattsPerM2Sr(1.0, wavelengthNm);
    return desaturateIntoGamut(xyzToLinearSrgb(cieXyz)) * (kLumensPerWatt * radiance);
}

glm::dvec3 lineLinearSrgbPerRayleigh(EmissionLine line)
{
    const LineInfo& info = lineInfo(line);
    return lineLinearSrgbPerRayleigh(info.wavelengthNm, info.cieXyz);
}

} // namespace aurorawall::physics
