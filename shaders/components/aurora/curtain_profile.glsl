// The electron flux across and along a curtain, relative to its peak: from the fluid_detail or the
// plasma simulation's frames when the scene lists one, else a smooth Gaussian. s: arclength along the curtain
// (km), u: signed distance across it (km), c: the curtain.
const int MAX_CURTAINS = 16;
// Per curtain: detail offset along the curtain (km, drift reduced on the CPU), detail phase
// (0 smooth ... 1 turbulent), lateral scale (simulation sigma / curtain sigma, or 1 / sigma), -.
uniform vec4 uCurtainDetail[MAX_CURTAINS];

#if defined(HAS_FLUID_DETAIL) || defined(HAS_PLASMA)
uniform sampler2DArray uFluxColumns; // x: along (periodic), y: frame, layer: entry across; the flux (1/km) and
                                 // its running integrals across at the cell centres
                                 // (src/components/fluid_detail/simulation/flux_columns.h)
uniform vec4 uFluxStrip;         // strip length km, strip width km, frame count, peak scale

// The running integrals (C, M) across the strip at across position a (simulation km) of the column at
// coord = (along, frame) (flux_column.glsl, fluxColumnValue), and the flux F there: the texture
// filters along and between frames only; across, the entry at the centre below a (its layer) is
// extended in float.
vec3 fluxColumnAt(vec2 coord, float across)
{
    float rows = float(textureSize(uFluxColumns, 0).z);
    float cellWidth = uFluxStrip.y / (rows - 1.0);
    float a = clamp(across, -0.5 * uFluxStrip.y, 0.5 * uFluxStrip.y);
    float position = (a + 0.5 * uFluxStrip.y) / cellWidth - 0.5; // in cell centres
    float below = clamp(floor(position), -1.0, rows - 2.0);
    vec4 texel = textureLod(uFluxColumns, vec3(coord, below + 1.0), 0.0);
    float centre = (below + 0.5) * cellWidth - 0.5 * uFluxStrip.y;
    float flux = abs(across) < 0.5 * uFluxStrip.y ? texel.z + texel.w * (a - centre) / cellWidth : 0.0;
    return vec3(fluxColumnValue(texel, centre, a - centre, cellWidth), flux);
}
#endif

// The profile's column across the curtain between u0 and u1 (km, either order): (∫ profile du,
// ∫ u profile du, the profile's mean at u0 and u1) in km, km² and 1, for integrating a ray step
// across a thin curtain in closed form (aurora_curtains.glsl). Exact for the smooth Gaussian and for
// the frames as the texture interpolates them (linear between cell centres).
vec3 curtainColumn(int c, float s, float u0, float u1)
{
    vec4 detail = uCurtainDetail[c];
    float a0 = u0 * detail.z;
    float a1 = u1 * detail.z;
#if defined(HAS_FLUID_DETAIL) || defined(HAS_PLASMA)
    float frame = detail.y * (uFluxStrip.z - 1.0);
    vec2 coord = vec2((s + detail.x) / uFluxStrip.x, (frame + 0.5) / uFluxStrip.z);
    vec3 lo = fluxColumnAt(coord, a0);
    vec3 hi = fluxColumnAt(coord, a1);
    return uFluxStrip.w * vec3((hi.x - lo.x) / detail.z, (hi.y - lo.y) / (detail.z * detail.z), 0.5 * (lo.z + hi.z));
#else
    return vec3(gaussianMass(a0, a1) / detail.z, gaussianMoment(a0, a1) / (detail.z * detail.z),
                0.5 * (exp(-0.5 * a0 * a0) + exp(-0.5 * a1 * a1)));
#endif
}

// The length along the curtain over which its flux is resolved (km): the frames' cell along (the
// texture interpolates linearly between cells); unbounded for the smooth Gaussian, which does not
// change along the curtain.
float fluxCellAlongKm()
{
#if defined(HAS_FLUID_DETAIL) || defined(HAS_PLASMA)
    return uFluxStrip.x / float(textureSize(uFluxColumns, 0).x);
#else
    return 1.0e30;
#endif
}
