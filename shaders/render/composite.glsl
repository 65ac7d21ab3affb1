// Compositing along one ray (Lawlor & Genetti, section 3.1 and figure 8): the layers a ray
// meets are found by intersection and composited front to back in their known order:
// aurora (emissive) -> lower atmosphere (absorbs, glows) -> aurora again -> planet or sky.
// The shells never overlap, so each aurora segment is wholly in front of or behind the
// lower atmosphere. Viewers inside the atmosphere or the aurora layer start mid-sequence.
const float FAR_KM = 1e30;

vec3 shadeRay(vec3 o, vec3 d)
{
    vec3 radiance = vec3(0.0);
    float tEnd = FAR_KM;
    bool hitsGround = false;
#ifdef HAS_PLANET
    if (uCameraAltitudeKm < 0.0)
        return vec3(0.0); // inside the rock
    vec2 ground = raySphere(o, d, uPlanetRadiusKm, uCameraAltitudeKm);
    if (ground.x <= ground.y && ground.y > 0.0) {
        hitsGround = true;
        tEnd = max(ground.x, 0.0);
    }
#endif

    vec3 transmittance = vec3(1.0); // of the lower atmosphere, for whatever lies behind it
    float atmosphereEnd = -1.0;
#ifdef HAS_ATMOSPHERE
    vec2 air = raySphere(o, d, uPlanetRadiusKm + uAtmosphereTopKm, uCameraAltitudeKm - uAtmosphereTopKm);
    air = vec2(max(air.x, 0.0), min(air.y, tEnd));
    if (air.x < air.y) {
        float airmass = airmassSegment(o, d, air.x, air.y);
        transmittance = exp(-uExtinctionPerKm * airmass);
        radiance += uSkyGlow * (vec3(1.0) - transmittance);
        atmosphereEnd = air.y;
    }
#ifdef HAS_SKY
    radiance += skyRadiance(o, d, tEnd); // in-scattered light, already attenuated along the view ray
#endif
#endif

#ifdef HAS_AURORA
    ShellSegments shell = rayShell(o, d, uPlanetRadiusKm + uAuroraBottomKm, uCameraAltitudeKm - uAuroraBottomKm,
                                   uPlanetRadiusKm + uAuroraTopKm, uCameraAltitudeKm - uAuroraTopKm, tEnd);
    if (shell.first.x < shell.first.y)
        radiance += auroraSegment(o, d, shell.first) * (shell.first.x >= atmosphereEnd ? transmittance : vec3(1.0));
    if (shell.second.x < shell.second.y)
        radiance += auroraSegment(o, d, shell.second) * (shell.second.x >= atmosphereEnd ? transmittance : vec3(1.0));
#endif

#ifdef HAS_PLANET
    if (hitsGround) {
        vec3 ground = uPlanetRadiance;
#ifdef HAS_PLANET_TEXTURE
        ground += nightLights(normalize(o + tEnd * d));
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
