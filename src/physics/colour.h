#pragma once
// Colour and radiance of emission lines (the aurora's, the airglow's): CIE 1931 XYZ → linear sRGB (IEC 61966-2-1),
// gamut mapping by desaturation at constant luminance, rayleigh → radiance.
// See docs/aurora-physics.md, "Colour" and "Units".
#include "physics/emission_lines.h"

#include <glm/glm.hpp>

namespace aurorawall::physics {

// Linear sRGB from CIE XYZ with the IEC 61966-2-1 matrix (D65 white: XYZ (0.9505, 1, 1.089) → (1, 1, 1)).
glm::dvec3 xyzToLinearSrgb(glm::dvec3 xyz);

// Luminance of a linear sRGB colour, Y = 0.2126 R + 0.7152 G + 0.0722 B (IEC 61966-2-1).
double linearSrgbLuminance(glm::dvec3 rgb);

// Gamut mapping: c' = Y·(1,1,1) + s·(c − Y·(1,1,1)) with Y = luminance(c) ≥ 0 and the largest s in
// [0, 1] making every component ≥ 0, i.e. s = min over negative components c_k of Y/(Y − c_k).
// Moves the colour toward the D65 white along a straight line in XYZ, so Y and the hue (the direction
// from the white point in the xy chromaticity plane) are kept exactly; only the saturation drops.
// Components above 1 are kept (the renderer works in HDR).
glm::dvec3 desaturateIntoGamut(glm::dvec3 rgb);

// 1 R = 1e10 photons m⁻² s⁻¹ (column) ↔ radiance 1e10/(4π) photons m⁻² s⁻¹ sr⁻¹ (Hunten et al. 1956).
double rayleighFromColumnRate(double photonsPerCm2PerS);
// Radiance of a line of `rayleigh` R at wavelength λ: 1e10/(4π)·R·hc/λ, W m⁻² sr⁻¹.
double radianceWattsPerM2Sr(double rayleigh, double wavelengthNm);

// Linear sRGB of one rayleigh of the line, gamut mapped, scaled to absolute luminance: Y in cd/m² is
// 683 lm/W · ȳ(λ) · radiance (CIE photopic, monochromatic). For uAuroraLineRgb.
glm::dvec3 lineLinearSrgbPerRayleigh(EmissionLine line);
// The same for any line, given its wavelength and CIE 1931 2° colour matching values (x̄, ȳ, z̄).
glm::dvec3 lineLinearSrgbPerRayleigh(double wavelengthNm, glm::dvec3 cieXyz);

} // namespace aurorawall::physics
