#include "io/tone_map.h"

#include <glm/glm.hpp>

#include <cmath>

namespace aurorawall::io {

namespace {

constexpr double halfMax = 65504.0; // largest finite IEEE half, as HALF_MAX in Imath's half.h

double sanitize(double x) { return std::isnan(x) ? 0.0 : glm::clamp(x, 0.0, halfMax); }

} // namespace

double srgbEncode(double linear)
{
    if (linear <= 0.0031308)
        return 12.92 * linear;
    return 1.055 * std::pow(linear, 1.0 / 2.4) - 0.055;
}

glm::dvec3 acesFilmic(glm::dvec3 x)
{
    const double a = 2.51, b = 0.03, c = 2.43, d = 0.59, e = 0.14;
    return glm::clamp((x * (a * x + b)) / (x * (c * x + d) + e), 0.0, 1.0);
}

glm::dvec3 magnitudeGamma(glm::dvec3 color)
{
    const double brightness = glm::length(color);
    if (brightness <= 0.0)
        return glm::dvec3(0.0);
    return color * std::pow(brightness, 1.0 / 2.2 - 1.0);
}

glm::dvec3 toneMapPixel(glm::dvec3 radiance, const ToneMap& toneMap)
{
    const glm::dvec3 x = toneMap.exposure * radiance;
    const glm::dvec3 linear(sanitize(x.r), sanitize(x.g), sanitize(x.b));
    if (toneMap.curve == ToneMap::Curve::MagnitudeGamma)
        return glm::clamp(magnitudeGamma(linear), 0.0, 1.0);
    const glm::dvec3 mapped = acesFilmic(linear);
    return glm::clamp(glm::dvec3(srgbEncode(mapped.r), srgbEncode(mapped.g), srgbEncode(mapped.b)), 0.0, 1.0);
}

} // namespace aurorawall::io
