#include "io/tone_map.h"

#include "common/glsl.h"

#include <cmath>

namespace aurorawall::io {

namespace f64 {
AURORAWALL_GLSL_PRECISION(double)
#include "render/tone_map.glsl"
} // namespace f64

namespace {

constexpr double halfMax = 65504.0; // largest finite IEEE half, as HALF_MAX in Imath's half.h

double sanitize(double x) { return std::isnan(x) ? 0.0 : glm::clamp(x, 0.0, halfMax); }

} // namespace

int toneCurveCode(ToneMap::Curve curve)
{
    return curve == ToneMap::Curve::MagnitudeGamma ? f64::TONE_MAP_MAGNITUDE_GAMMA : f64::TONE_MAP_ACES_FILMIC;
}

double srgbEncode(double linear) { return f64::srgbEncode(linear); }

glm::dvec3 acesFilmic(glm::dvec3 x) { return f64::acesFilmic(x); }

glm::dvec3 magnitudeGamma(glm::dvec3 color) { return f64::magnitudeGamma(color); }

glm::dvec3 toneMapPixel(glm::dvec3 radiance, const ToneMap& toneMap)
{
    const glm::dvec3 x = toneMap.exposure * radiance;
    return f64::toneCurve(glm::dvec3(sanitize(x.r), sanitize(x.g), sanitize(x.b)), toneCurveCode(toneMap.curve));
}

} // namespace aurorawall::io
