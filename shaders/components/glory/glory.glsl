// glory: the cloud deck (cloud_deck.glsl) lit by the Sun or the Moon, with the glory around the
// antisolar point: the light single-scattered by the drops, from the precomputed table of their
// size-averaged Mie phase function over the angle from the antisolar point (smeared by the light's
// disc), over the deck's diffuse light. The deck is opaque: it ends the rays that meet it.
uniform float uDeckBaseKm;
uniform float uDeckTopKm;
uniform float uDeckOpticalThickness;
uniform float uDeckAsymmetry;
uniform vec3 uGloryLightDirection; // unit, planet frame, toward the light
uniform vec3 uGloryLightRgb;       // its illuminance above the atmosphere per linear-sRGB primary (lux)
uniform vec3 uGloryAngleSpans;     // the table's angle segments (radians): the glory, the middle, the forward peak
uniform vec3 uGloryAngleCounts;    // and their samples
uniform int uGlorySampling;        // 0: the colour table; 1, 2: wavelengths per pixel (uniform, importance)
uniform int uGloryWavelengthsPerPixel;
uniform sampler2D uGloryColour;    // linear sRGB per angle: the light's E P / 4 pi over all wavelengths
uniform sampler2D uGloryPhase;     // P(angle, wavelength), smeared by the light's disc
uniform sampler2D uGlorySamples;   // per u in [0, 1]: wavelength coordinate, XYZ weight E cmf / (4 pi pdf)

// The deck ends the rays that meet it before the ground; it hides the ground.
Ray boundByCloudDeck(Ray ray)
{
    float t = cloudDeckHit(ray.origin, ray.direction, uPlanetRadiusKm, ray.altitude, uDeckBaseKm, uDeckTopKm);
    if (t >= 0.0 && t < ray.end) {
        ray.end = t;
        ray.groundT = -1.0;
    }
    return ray;
}

// A number in [0, 1) from the ray's direction (the per-pixel offset of the wavelengths; Jenkins'
// one-at-a-time mix of the direction's bits): the same for the same direction on every rank.
float gloryPixelJitter(vec3 d)
{
    uvec3 bits = floatBitsToUint(d);
    uint h = bits.x;
    h += h << 10u; h ^= h >> 6u; h += bits.y;
    h += h << 10u; h ^= h >> 6u; h += bits.z;
    h += h << 10u; h ^= h >> 6u;
    h += h << 3u; h ^= h >> 11u; h += h << 15u;
    return float(h >> 8u) / 16777216.0;
}

// The glory's light per unit geometric factor at gamma from the antisolar point (linear sRGB).
vec3 gloryColour(float gamma, vec3 direction)
{
    float samples = uGloryAngleCounts.x + uGloryAngleCounts.y + uGloryAngleCounts.z;
    float u = (gloryAngleIndex(gamma, uGloryAngleSpans, uGloryAngleCounts) + 0.5) / samples;
    if (uGlorySampling == 0)
        return texture(uGloryColour, vec2(u, 0.5)).rgb;
    float jitter = gloryPixelJitter(direction);
    vec3 xyz = vec3(0.0);
    for (int k = 0; k < uGloryWavelengthsPerPixel; ++k) {
        vec4 s = texture(uGlorySamples, vec2((float(k) + jitter) / float(uGloryWavelengthsPerPixel), 0.5));
        xyz += s.yzw * texture(uGloryPhase, vec2(u, s.x)).r;
    }
    return desaturateIntoGamut(xyzToLinearSrgb(xyz / float(uGloryWavelengthsPerPixel)));
}

// The light's transmittance through the lower atmosphere (the role of that name, when a listed
// component provides it) down to a deck point `altitude` km up.
vec3 gloryLightTransmittance(vec3 p, float altitude)
{
#ifdef HAS_LOWER_ATMOSPHERE
    vec2 top = raySphere(p, uGloryLightDirection, uPlanetRadiusKm + uAtmosphereTopKm, altitude - uAtmosphereTopKm);
    return exp(-uExtinctionPerKm * airmassSegment(p, uGloryLightDirection, 0.0, max(top.y, 0.0)));
#else
    return vec3(1.0);
#endif
}

// The deck where it ends the ray, seen through the lower atmosphere.
Ray shadeGlory(Ray ray)
{
    float t = cloudDeckHit(ray.origin, ray.direction, uPlanetRadiusKm, ray.altitude, uDeckBaseKm, uDeckTopKm);
    if (t < 0.0 || t != ray.end)
        return ray;
    vec3 p = ray.origin + t * ray.direction;
    vec3 up = normalize(p);
    float mu0 = dot(up, uGloryLightDirection);
    if (mu0 <= 0.0)
        return ray;
    bool above = ray.altitude >= uDeckTopKm, below = ray.altitude <= uDeckBaseKm;
    float altitude = above ? uDeckTopKm : (below ? uDeckBaseKm : ray.altitude);
    vec3 deck = uGloryLightRgb * cloudDeckDiffuse(mu0, uDeckOpticalThickness, uDeckAsymmetry, above, below);
    if (above) {
        float mu = max(-dot(up, ray.direction), 1e-6);
        float gamma = angleBetween(ray.direction, -uGloryLightDirection);
        deck += gloryColour(gamma, ray.direction) * singleScatteringFactor(mu0, mu, uDeckOpticalThickness);
    }
    ray.radiance += deck * gloryLightTransmittance(p, altitude) * ray.transmittance;
    return ray;
}
