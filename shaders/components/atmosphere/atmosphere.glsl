// Lower atmosphere: density exp(-h / H) relative to sea level, up to uAtmosphereTopKm.
// Light crossing it is attenuated by T = exp(-extinction * airmass); the path adds the night-sky
// glow uSkyGlow (1 - T) that the air scatters toward the viewer. Airmass is in sea-level-equivalent km.
uniform float uAtmosphereTopKm;
uniform float uScaleHeightKm;
uniform vec3 uExtinctionPerKm;
uniform vec3 uSkyGlow;

// Airmass of the segment [t0, t1] of the ray o + t d: the default closed form
// (shaders/physics/atmosphere/airmass_chapman.glsl, docs/airmass.md): max relative error 3.7e-5 in float
// (CPU and llvmpipe) over the whole test ray set, cheaper than a 16-step march.
float airmassSegment(vec3 o, vec3 d, float t0, float t1)
{
    return airmassChapmanAsymptotic(o, d, t0, t1, uScaleHeightKm, uPlanetRadiusKm);
}

// The lower atmosphere from the ground up to uAtmosphereTopKm: it attenuates whatever lies behind
// it and adds its glow.
Ray shadeAtmosphere(Ray ray)
{
    ray.lowerAtmosphere = lowerShellSegment(ray, uPlanetRadiusKm, uAtmosphereTopKm);
    if (ray.lowerAtmosphere.x < ray.lowerAtmosphere.y) {
        float airmass = airmassSegment(ray.origin, ray.direction, ray.lowerAtmosphere.x, ray.lowerAtmosphere.y);
        ray.transmittance = exp(-uExtinctionPerKm * airmass);
        ray.radiance += uSkyGlow * (vec3(1.0) - ray.transmittance);
    }
    return ray;
}
