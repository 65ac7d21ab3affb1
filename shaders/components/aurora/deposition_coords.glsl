// Texture coordinates of the aurora tables (docs/aurora-physics.md, "Tables").
// One text for GLSL and C++ (src/common/glsl.h): `real` is float on the GPU, float or double on the CPU.
//
// The deposition table is a 2D texture: texel (i, j) holds the value at altitude
// z_i = axes.x + i·axes.y km and energy E_j = exp(axes.z + j·axes.w) keV, i < size.x, j < size.y.
// The line-yield table is a 1D row on the same altitude axis. Texel centres sit at (i + 0.5)/size,
// so GL_LINEAR filtering interpolates linearly in altitude and in ln E between the stored values.
// The per-curtain emission rows (src/components/aurora/physics/emission_table.h) hold nodes at
// z_k = axes.x + k·axes.y km, k < axes.z, on the same kind of texel centres.

// (u, v) of altitude z (km) and energy E (keV); axes = (z_0, Δz, ln E_0, Δln E), size = texel counts.
vec2 depositionTexCoord(real altitudeKm, real energyKeV, vec4 axes, vec2 size)
{
    real i = (altitudeKm - axes.x) / axes.y;
    real j = (log(energyKeV) - axes.z) / axes.w;
    return (vec2(i, j) + vec2(real(0.5), real(0.5))) / size;
}

// u of altitude z (km) in an emission row; axes = (z_0 km, node spacing km, node count).
real emissionTexCoord(real altitudeKm, vec3 axes)
{
    return ((altitudeKm - axes.x) / axes.y + real(0.5)) / axes.z;
}

// The tables store decibels, 10·log10(value); back to the value: 10^(dB/10) = 2^(dB·log2(10)/10).
real decibelsToValue(real decibels)
{
    return exp2(decibels * real(0.332192809488736235));
}
