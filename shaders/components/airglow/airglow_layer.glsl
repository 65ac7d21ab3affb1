// The column of one airglow layer along a ray, in closed form (shared by the shader and the C++
// tests, src/common/glsl.h; needs physics/atmosphere/airmass_common.glsl and airmass_chapman.glsl).
//
// A layer's volume emission rate (rayleigh per km) above its base height b is the difference of two
// exponentials, zero below b (a Chapman-like layer: a sharp rise, a slower fall):
//   eps(h) = A (exp(-(h - b)/Hu) - exp(-(h - b)/Hl)),  Hl = Hu/2,
// so its zenith column is A (Hu - Hl), and along any part of a ray above the base it is A times the
// difference of two exponential columns, each the airmass of an exponential atmosphere of scale
// height Hu or Hl whose "ground" is the sphere of radius R + b: the Chapman closed form of the
// airmass work (airmassChapmanAsymptotic), not a march.
// layer: (b km, Hu km, Hl km, A rayleigh per km); rBase = R + b; [t0, t1] lies wholly above rBase.
real airglowColumn(vec3 origin, vec3 direction, real t0, real t1, vec4 layer, real rBase)
{
    real upper = airmassChapmanAsymptotic(origin, direction, t0, t1, layer.y, rBase);
    real lower = airmassChapmanAsymptotic(origin, direction, t0, t1, layer.z, rBase);
    return layer.w * max(upper - lower, real(0.0));
}
