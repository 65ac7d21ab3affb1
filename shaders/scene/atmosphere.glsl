// Lower atmosphere: density exp(-h / H) relative to sea level, up to uAtmosphereTopKm.
// Light crossing it is attenuated by T = exp(-extinction * airmass); the path adds the night-sky
// glow uSkyGlow (1 - T) that the air scatters toward the viewer. Airmass is in sea-level-equivalent km.
uniform float uAtmosphereTopKm;
uniform float uScaleHeightKm;
uniform vec3 uExtinctionPerKm;
uniform vec3 uSkyGlow;

// Airmass of the segment [t0, t1] by a 16-step midpoint rule (first light; issue 4 brings
// the closed forms measured against an exact reference).
float airmassSegment(vec3 o, vec3 d, float t0, float t1)
{
    const int steps = 16;
    float dt = (t1 - t0) / float(steps);
    float sum = 0.0;
    for (int i = 0; i < steps; ++i) {
        float h = length(o + (t0 + (float(i) + 0.5) * dt) * d) - uPlanetRadiusKm;
        sum += exp(-max(h, 0.0) / uScaleHeightKm);
    }
    return sum * dt;
}
