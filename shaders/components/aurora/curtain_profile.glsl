// The electron flux across and along a curtain, relative to its peak: from the fluid_detail or the
// plasma simulation's frames when the scene lists one, else a smooth Gaussian. s: arclength along the curtain
// (km), u: signed distance across it (km), c: the curtain.
const int MAX_CURTAINS = 16;
// Per curtain: detail offset along the curtain (km, drift reduced on the CPU), detail phase
// (0 smooth ... 1 turbulent), lateral scale (simulation sigma / curtain sigma, or 1 / sigma), -.
uniform vec4 uCurtainDetail[MAX_CURTAINS];

#if defined(HAS_FLUID_DETAIL) || defined(HAS_PLASMA)
uniform sampler3D uFluxFrames;   // x: along (periodic), y: across, z: frame; flux 1/km
uniform vec4 uFluxStrip;         // strip length km, strip width km, frame count, peak scale
#endif

float curtainProfile(int c, float s, float u)
{
    vec4 detail = uCurtainDetail[c];
#if defined(HAS_FLUID_DETAIL) || defined(HAS_PLASMA)
    float across = u * detail.z; // in the simulation's km
    if (abs(across) >= 0.5 * uFluxStrip.y)
        return 0.0;
    // Texel centres at (i + 1/2)/n on every axis (src/components/fluid_detail/simulation/curtain_detail.h, docs/fluid.md).
    float frame = detail.y * (uFluxStrip.z - 1.0);
    vec3 coord = vec3((s + detail.x) / uFluxStrip.x, across / uFluxStrip.y + 0.5, (frame + 0.5) / uFluxStrip.z);
    return uFluxStrip.w * textureLod(uFluxFrames, coord, 0.0).r;
#else
    float x = u * detail.z; // in standard deviations
    return exp(-0.5 * x * x);
#endif
}
