#pragma once
// Tone mapping of linear radiance to display values in [0, 1] for the 8-bit sRGB preview.
// The curves are shaders/render/tone_map.glsl, the same text the window shader runs, here in double.
#include <glm/vec3.hpp>

namespace aurorawall::io {

struct ToneMap {
    enum class Curve {
        MagnitudeGamma, // Lawlor & Genetti's hue-preserving gamma on the colour vector's magnitude
        AcesFilmic,     // Narkowicz 2015 fit of the ACES filmic curve, then the sRGB transfer function
    };
    Curve curve = Curve::AcesFilmic;
    double exposure = 1.0; // multiplies radiance before the curve
};

// The display value of one pixel, each component in [0, 1]:
//   1. x = exposure * radiance;
//   2. per component: NaN -> 0, negative (out of gamut) -> 0, above HALF_MAX (65504) -> HALF_MAX,
//      the same range the EXR stores, and it keeps both curves finite (and the ACES fit monotone);
//   3. the curve; 4. clamp to [0, 1].
glm::dvec3 toneMapPixel(glm::dvec3 radiance, const ToneMap& toneMap);

// The curve's code in tone_map.glsl (TONE_MAP_ACES_FILMIC, TONE_MAP_MAGNITUDE_GAMMA), for uniforms.
int toneCurveCode(ToneMap::Curve curve);

// The pieces of tone_map.glsl in double (see there): the sRGB transfer function, Narkowicz's ACES
// fit (clamped to [0, 1]) and Lawlor & Genetti's magnitude-preserving gamma (not clamped).
double srgbEncode(double linear);
glm::dvec3 acesFilmic(glm::dvec3 x);
glm::dvec3 magnitudeGamma(glm::dvec3 color);

} // namespace aurorawall::io
