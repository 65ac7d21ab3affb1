// Aurora deposition and line emission from the precomputed tables (docs/aurora-physics.md).
// Needs aurora/deposition_coords.glsl before it. Textures: GL_LINEAR, GL_CLAMP_TO_EDGE, no mipmaps.
uniform sampler2D uAuroraDeposition;  // R32F, x: altitude, y: ln E; 10·log10(keV cm⁻³ s⁻¹ per erg cm⁻² s⁻¹)
uniform vec4 uAuroraDepositionAxes;   // (z_0 km, Δz km, ln E_0, Δln E)
uniform vec2 uAuroraDepositionSize;   // (altitude count, energy count)
uniform sampler2D uAuroraLineYield;   // RGBA32F, width = altitude count, height 1: photons per keV
                                      // deposited for 427.8 nm, 557.7 nm, 630.0 nm, N2 1PG
uniform vec3 uAuroraLineRgb[4];       // linear sRGB (cd/m²) of one rayleigh of each line

// Energy deposition rate at altitude z (km) for electrons of (characteristic) energy E (keV),
// keV cm⁻³ s⁻¹ per erg cm⁻² s⁻¹ of incident energy flux.
float auroraDeposition(float altitudeKm, float energyKeV)
{
    vec2 uv = depositionTexCoord(altitudeKm, energyKeV, uAuroraDepositionAxes, uAuroraDepositionSize);
    return decibelsToValue(texture(uAuroraDeposition, uv).r);
}

// Volume emission rates of the four emissions, photons cm⁻³ s⁻¹ per erg cm⁻² s⁻¹.
vec4 auroraLineEmission(float altitudeKm, float energyKeV)
{
    vec2 uv = depositionTexCoord(altitudeKm, energyKeV, uAuroraDepositionAxes, uAuroraDepositionSize);
    vec4 yield = texture(uAuroraLineYield, vec2(uv.x, 0.5));
    return decibelsToValue(texture(uAuroraDeposition, uv).r) * yield;
}

// Linear sRGB added per km of path per erg cm⁻² s⁻¹: 1 photon cm⁻³ s⁻¹ over 1 km is a column of
// 1e5 photons cm⁻² s⁻¹ = 0.1 R. Multiply by the local energy flux and the step length in km.
vec3 auroraEmissionRgbPerKm(float altitudeKm, float energyKeV)
{
    vec4 rate = auroraLineEmission(altitudeKm, energyKeV) * 0.1;
    return rate.x * uAuroraLineRgb[0] + rate.y * uAuroraLineRgb[1] + rate.z * uAuroraLineRgb[2] +
           rate.w * uAuroraLineRgb[3];
}
