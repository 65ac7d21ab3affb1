// Single-scattering sky lit by several sources (requires airmass_common.glsl and
// airmass_chapman.glsl). One text for GLSL and C++ (src/common/glsl.h).
//
// Rayleigh single scattering along the view ray o + t·d̂, t ∈ [ta, tb] (the part inside the air):
//   L = Σ_l E_l·β·p(d̂·ŝ_l) ∫_ta^tb ρ(t)·exp(−β·(I_view(t) + I_l(t)))·V_l(t) dt        (cd/m²)
// with ρ = exp(−(r − R)/H) the density relative to the ground, β the ground-level Rayleigh scattering
// coefficient (per km, R/G/B), I_view(t) the airmass from the viewer to the point, I_l(t) the airmass
// from the point toward light l to the top of the air, V_l ∈ {0, 1} whether the ground hides light l,
// p the Rayleigh phase function and E_l the light's illuminance at the top of the atmosphere (lux per
// primary). Bruneton & Neyret, "Precomputed atmospheric scattering" (2008), eq. 1–5, single scattering.
//
// The integral is the midpoint rule with M equal steps ("outer march"). I_view accumulates the same
// midpoint samples. I_l is the seed-002 point: a closed form (airmassHalfLine, the half-line column of
// the default airmass method, docs/airmass.md) replaces the classic inner march, so N lights cost N
// closed forms per step instead of N·K density samples. The nested march (K midpoint steps toward
// each light) is kept in the same text as the reference and the cost yardstick.

const int SKY_MAX_LIGHTS = 8;
const int SKY_LIGHT_CLOSED_FORM = 0;
const int SKY_LIGHT_NESTED_MARCH = 1;

// The air: an exponential atmosphere between the ground and the top sphere.
struct SkyAtmosphere {
    real planetRadius;        // R, km
    real topRadius;           // km from the planet's centre; no air above it
    real scaleHeight;         // H, km
    vec3 rayleighScattering;  // β at the ground, per km, for the R, G, B primaries
};

// Rayleigh phase function per steradian, p(μ) = 3/(16π)·(1 + μ²), μ the cosine of the scattering
// angle (Chandrasekhar, Radiative Transfer (1950); Bruneton & Neyret 2008, eq. 2).
real skyRayleighPhase(real mu)
{
    return real(3) / (real(16) * kPi) * (real(1) + mu * mu);
}

// Both roots (near, far) of |o + t·d̂|² = radius², d̂ a unit vector, or (1, −1) when the ray misses.
// Stable form (Numerical Recipes 3rd ed. §5.6): with b = o·d̂ and c = (|o| − radius)(|o| + radius)
// (factored, so it stays accurate on the sphere), q = −b − sign(b)·√(b² − c); the roots are q and c/q.
vec2 skyRaySphere(vec3 origin, vec3 d, real radius)
{
    real distance = length(origin);
    real b = dot(origin, d);
    real c = (distance - radius) * (distance + radius);
    real discriminant = b * b - c;
    if (discriminant < real(0)) return vec2(real(1), real(-1));
    real q = b >= real(0) ? -b - sqrt(discriminant) : -b + sqrt(discriminant);
    real other = q != real(0) ? c / q : real(0);
    return vec2(min(q, other), max(q, other));
}

// Distance from a point inside the sphere to where the ray leaves it: −b + √(b² − c), written as
// −c/(b + √(b² − c)) when b > 0 so that it does not cancel (same b and c as skyRaySphere).
real skySphereExit(vec3 origin, vec3 d, real radius)
{
    real distance = length(origin);
    real b = dot(origin, d);
    real c = (distance - radius) * (distance + radius);
    real root = sqrt(max(b * b - c, real(0)));
    return b > real(0) ? max(-c, real(0)) / (b + root) : root - b;
}

// Airmass (km) from the point p toward the light ŝ up to the top of the air,
//   I_l = ∫_0^{t_top} exp(−(|p + t·ŝ| − R)/H) dt,
// by the midpoint rule with lightSteps steps (SKY_LIGHT_NESTED_MARCH) or by the closed form
// (SKY_LIGHT_CLOSED_FORM), the half-line column airmassHalfLine from the ray frame (y, x) of p and ŝ.
// The closed form runs on to infinity: the air above the top adds e^{−(top − h)/H} of the column, below
// 4e-6 for a top 100 km above the ground and H = 8 km.
real skyLightAirmass(vec3 p, vec3 s, vec3 frame, SkyAtmosphere atmosphere, int lightMethod, int lightSteps)
{
    real R = atmosphere.planetRadius;
    real H = atmosphere.scaleHeight;
    if (lightMethod == SKY_LIGHT_CLOSED_FORM) return airmassHalfLine(length(p), frame.y, frame.x, H, R);
    real tTop = skySphereExit(p, s, atmosphere.topRadius);
    real dt = tTop / real(lightSteps);
    real sum = real(0);
    for (int j = 0; j < lightSteps; ++j) {
        sum += exp(min((R - length(p + (real(j) + real(0.5)) * dt * s)) / H, real(60)));
    }
    return sum * dt;
}

// Transmittance from the top of the air to p along the light ŝ, exp(−β·I_l), or 0 when the ground
// hides the light (V_l = 0): the ray toward it descends (x = p·ŝ < 0) and its closest approach to the
// centre, y = |p|·sin∠(p, ŝ) (airmassRayFrame's accurate form), lies below the ground.
vec3 skyLightTransmittance(vec3 p, vec3 s, SkyAtmosphere atmosphere, int lightMethod, int lightSteps)
{
    vec3 frame = airmassRayFrame(p, s, real(0), real(0)); // (y, x, x) with x = p·ŝ
    if (frame.y < real(0) && frame.x < atmosphere.planetRadius) return vec3(real(0));
    return exp(-atmosphere.rayleighScattering * skyLightAirmass(p, s, frame, atmosphere, lightMethod, lightSteps));
}

// The sky radiance L above (cd/m² when the illuminances are in lux), marched with viewSteps midpoint
// steps over the part of [0, tMax] that lies inside the air and in front of the ground.
// lightDirections are unit vectors toward the lights in the planet frame; only the first lightCount
// (≤ SKY_MAX_LIGHTS) are used. A zero direction or a ray that misses the air gives 0.
vec3 skyScattering(vec3 origin, vec3 direction, real tMax, SkyAtmosphere atmosphere, int lightCount,
                   vec3 lightDirections[SKY_MAX_LIGHTS], vec3 lightIlluminance[SKY_MAX_LIGHTS],
                   int viewSteps, int lightMethod, int lightSteps)
{
    real directionLength = length(direction);
    if (!(directionLength > real(0))) return vec3(real(0));
    vec3 d = direction / directionLength;
    vec2 air = skyRaySphere(origin, d, atmosphere.topRadius);
    vec2 ground = skyRaySphere(origin, d, atmosphere.planetRadius);
    real tStart = max(air.x, real(0));
    real tEnd = min(air.y, tMax);
    if (ground.x <= ground.y && ground.x >= real(0)) tEnd = min(tEnd, ground.x);
    if (!(tEnd > tStart)) return vec3(real(0));

    real dt = (tEnd - tStart) / real(viewSteps);
    real viewAirmass = real(0);   // from the viewer to the start of the current step
    vec3 radiance = vec3(real(0));
    for (int i = 0; i < viewSteps; ++i) {
        vec3 p = origin + (tStart + (real(i) + real(0.5)) * dt) * d;
        real density = exp(min((atmosphere.planetRadius - length(p)) / atmosphere.scaleHeight, real(60)));
        vec3 viewTransmittance = exp(-atmosphere.rayleighScattering * (viewAirmass + real(0.5) * density * dt));
        for (int l = 0; l < lightCount; ++l) {
            radiance += lightIlluminance[l] * skyRayleighPhase(dot(d, lightDirections[l])) * density
                      * viewTransmittance * skyLightTransmittance(p, lightDirections[l], atmosphere, lightMethod, lightSteps);
        }
        viewAirmass += density * dt;
    }
    return radiance * atmosphere.rayleighScattering * dt;
}

// The renderer's sky: light-side airmass by the closed form.
vec3 skySingleScattering(vec3 origin, vec3 direction, real tMax, SkyAtmosphere atmosphere, int lightCount,
                         vec3 lightDirections[SKY_MAX_LIGHTS], vec3 lightIlluminance[SKY_MAX_LIGHTS], int viewSteps)
{
    return skyScattering(origin, direction, tMax, atmosphere, lightCount, lightDirections, lightIlluminance,
                         viewSteps, SKY_LIGHT_CLOSED_FORM, 0);
}

// The reference and yardstick: light-side airmass by a nested march of lightSteps steps per light.
vec3 skySingleScatteringNested(vec3 origin, vec3 direction, real tMax, SkyAtmosphere atmosphere, int lightCount,
                               vec3 lightDirections[SKY_MAX_LIGHTS], vec3 lightIlluminance[SKY_MAX_LIGHTS],
                               int viewSteps, int lightSteps)
{
    return skyScattering(origin, direction, tMax, atmosphere, lightCount, lightDirections, lightIlluminance,
                         viewSteps, SKY_LIGHT_NESTED_MARCH, lightSteps);
}
