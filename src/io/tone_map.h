#pragma once
// Tone mapping of linear radiance to display values in [0, 1] for the 8-bit sRGB preview.
// toneMapPixel is the per-pixel reference that the GLSL preview shader mirrors; the helpers below
// are written with GLSL built-ins only so that their bodies translate one to one.
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

// sRGB transfer function (OETF) of IEC 61966-2-1, linear -> encoded, for linear in [0, 1]:
// 12.92 x for x <= 0.0031308, else 1.055 x^(1/2.4) - 0.055.
double srgbEncode(double linear);

// Narkowicz 2015, "ACES Filmic Tone Mapping Curve": x (2.51 x + 0.03) / (x (2.43 x + 0.59) + 0.14),
// clamped to [0, 1] (his saturate); applied per component to non-negative linear values.
glm::dvec3 acesFilmic(glm::dvec3 x);

// Lawlor & Genetti, magnitude-preserving gamma: color * pow(length(color), 1/2.2 - 1), so the
// colour keeps its direction (hue and saturation) and its length becomes length^(1/2.2).
// Black stays black. The result is display-encoded; it is not clamped here.
glm::dvec3 magnitudeGamma(glm::dvec3 color);

} // namespace aurorawall::io
