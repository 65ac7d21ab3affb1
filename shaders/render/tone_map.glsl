// Tone curves from linear radiance (already multiplied by the exposure and made finite and
// non-negative) to display values in [0, 1]. Shared by the window shader (render/display.frag)
// and the PNG writer (src/io/tone_map.cpp, through src/common/glsl.h), so a window shows what
// wall.png shows.
const int TONE_MAP_ACES_FILMIC = 0;
const int TONE_MAP_MAGNITUDE_GAMMA = 1;

// sRGB transfer function (OETF) of IEC 61966-2-1, linear -> encoded, for linear in [0, 1]:
// 12.92 x for x <= 0.0031308, else 1.055 x^(1/2.4) - 0.055.
real srgbEncode(real x)
{
    return x <= real(0.0031308) ? real(12.92) * x : real(1.055) * pow(x, real(1.0) / real(2.4)) - real(0.055);
}

// Narkowicz 2015, "ACES Filmic Tone Mapping Curve": x (2.51 x + 0.03) / (x (2.43 x + 0.59) + 0.14),
// clamped to [0, 1] (his saturate); per component, for non-negative linear values.
vec3 acesFilmic(vec3 x)
{
    return clamp((x * (real(2.51) * x + real(0.03))) / (x * (real(2.43) * x + real(0.59)) + real(0.14)), real(0.0),
                 real(1.0));
}

// Lawlor & Genetti, magnitude-preserving gamma: colour * length(colour)^(1/2.2 - 1), so the colour
// keeps its direction (hue and saturation) and its length becomes length^(1/2.2). Black stays black.
vec3 magnitudeGamma(vec3 colour)
{
    real brightness = length(colour);
    return brightness > real(0.0) ? colour * pow(brightness, real(1.0) / real(2.2) - real(1.0)) : vec3(real(0.0));
}

// The display value, each component in [0, 1].
vec3 toneCurve(vec3 linear, int curve)
{
    if (curve == TONE_MAP_MAGNITUDE_GAMMA)
        return clamp(magnitudeGamma(linear), real(0.0), real(1.0));
    vec3 mapped = acesFilmic(linear);
    return clamp(vec3(srgbEncode(mapped.x), srgbEncode(mapped.y), srgbEncode(mapped.z)), real(0.0), real(1.0));
}
