// sky: single-scattering Rayleigh sky lit by up to SKY_MAX_LIGHTS sources (the Sun, the Moon,
// or several Sun positions), each source's light-side optical depth from the closed-form airmass
// (shaders/physics/atmosphere/sky.glsl; after C. Davis, Tectonics.js): several lights for the price of one.
// The air is the atmosphere component's (its top, scale height and extinction). Radiance in cd/m^2
// for illuminances in lux.
uniform int uSkyViewSteps;
uniform int uSkyLightMethod; // SKY_LIGHT_CLOSED_FORM or SKY_LIGHT_NESTED_MARCH (the reference)
uniform int uSkyLightSteps;
uniform int uSkyLightCount;
uniform vec3 uSkyLightDirection[SKY_MAX_LIGHTS];
uniform vec3 uSkyLightIlluminanceLux[SKY_MAX_LIGHTS];

vec3 skyRadiance(vec3 o, vec3 d, float tEnd)
{
    SkyAtmosphere air = SkyAtmosphere(uPlanetRadiusKm, uPlanetRadiusKm + uAtmosphereTopKm, uScaleHeightKm, uExtinctionPerKm);
    return skyScattering(o, d, tEnd, air, uSkyLightCount, uSkyLightDirection, uSkyLightIlluminanceLux,
                         uSkyViewSteps, uSkyLightMethod, uSkyLightSteps);
}

// In-scattered light, already attenuated along the view ray, up to where the ray ends.
Ray shadeSky(Ray ray)
{
    ray.radiance += skyRadiance(ray.origin, ray.direction, ray.end);
    return ray;
}
