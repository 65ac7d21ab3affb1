// Lower atmosphere: density exp(-h / H) relative to sea level, up to uAtmosphereTopKm.
// Light crossing it is attenuated by T = exp(-extinction * airmass); the path adds the night-sky
// glow uSkyGlow (1 - T) that the air scatters toward the viewer. Airmass is in sea-level-equivalent km.
uniform float uAtmosphereTopKm;
uniform float uScaleHeightKm;
uniform vec3 uExtinctionPerKm;
uniform vec3 uSkyGlow;

// Airmass of the segment [t0, t1] of the ray o + t d: the closed form measured as the most
// accurate per cost (shaders/atmosphere/airmass_chapman.glsl, docs/airmass.md): max relative
// error 1.1e-5 in float (CPU and llvmpipe) over the whole test ray set.
float airmassSegment(vec3 o, vec3 d, float t0, float t1)
{
    return airmassChapmanAsymptotic(o, d, t0, t1, uScaleHeightKm, uPlanetRadiusKm);
}
