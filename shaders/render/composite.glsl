// Compositing along one ray (Lawlor & Genetti, section 3.1 and figure 8): the layers the ray
// meets (render/layers.glsl) are composited front to back in their fixed order. The aurora is
// purely emissive; the lower atmosphere attenuates what lies behind it and adds its glow and,
// with the sky component, in-scattered light; the ground or the stars close the ray.
vec3 shadeRay(vec3 o, vec3 d)
{
#ifdef HAS_PLANET
    RayLayers layers = rayLayers(o, d, uPlanetRadiusKm, uCameraAltitudeKm,
#ifdef HAS_ATMOSPHERE
                                 uAtmosphereTopKm,
#else
                                 0.0,
#endif
#ifdef HAS_AURORA
                                 uAuroraBottomKm, uAuroraTopKm);
#else
                                 0.0, 0.0);
#endif
    if (layers.insideGround)
        return vec3(0.0);
    bool hitsGround = layers.groundT >= 0.0;
    float end = hitsGround ? layers.groundT : 1e30;
#else
    bool hitsGround = false;
    float end = 1e30;
#endif
    vec3 radiance = vec3(0.0);
    vec3 transmittance = vec3(1.0); // of the lower atmosphere, for whatever lies behind it

#ifdef HAS_ATMOSPHERE
    if (layers.atmosphere.x < layers.atmosphere.y) {
        float airmass = airmassSegment(o, d, layers.atmosphere.x, layers.atmosphere.y);
        transmittance = exp(-uExtinctionPerKm * airmass);
        radiance += uSkyGlow * (vec3(1.0) - transmittance);
    }
#ifdef HAS_SKY
    radiance += skyRadiance(o, d, end); // in-scattered light, already attenuated along the view ray
#endif
#endif

#ifdef HAS_AURORA
    if (layers.auroraNear.x < layers.auroraNear.y)
        radiance += auroraSegment(o, d, layers.auroraNear) *
                    (behindAtmosphere(layers.auroraNear, layers.atmosphere) ? transmittance : vec3(1.0));
    if (layers.auroraFar.x < layers.auroraFar.y)
        radiance += auroraSegment(o, d, layers.auroraFar) *
                    (behindAtmosphere(layers.auroraFar, layers.atmosphere) ? transmittance : vec3(1.0));
#endif

#ifdef HAS_PLANET
    if (hitsGround) {
        vec3 ground = uPlanetRadiance;
#ifdef HAS_PLANET_TEXTURE
        ground += nightLights(normalize(o + end * d));
#endif
        radiance += ground * transmittance;
    }
#endif
#ifdef HAS_STARS
    if (!hitsGround)
        radiance += starRadiance(d) * transmittance;
#endif
    return radiance;
}
