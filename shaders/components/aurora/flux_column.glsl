// The running integrals of tabulated flux frames across a curtain, for integrating a ray step across
// it in closed form (curtain_profile.glsl). One text for GLSL and C++ (src/common/glsl.h): `real` is
// float on the GPU, float or double on the CPU.

// The running integrals C(a) = ∫_{−w/2}^{a} F da' and M(a) = ∫_{−w/2}^{a} a' F da' of a flux F that is
// linear between cell centres (src/components/roles/flux_columns.h), from the
// table's entry at the centre c below a: texel = (C(c), M(c), F(c), F(c + Δ) − F(c)), x = a − c in
// [0, Δ]. With F = F(c) + k x', k = (F(c + Δ) − F(c))/Δ:
//   C(a) = C(c) + F(c) x + k x²/2,   M(a) = M(c) + c (C(a) − C(c)) + F(c) x²/2 + k x³/3.
vec2 fluxColumnValue(vec4 texel, real centre, real x, real cellWidth)
{
    real k = texel.w / cellWidth;
    real mass = x * (texel.z + real(0.5) * k * x);
    real moment = x * x * (real(0.5) * texel.z + k * x / real(3.0));
    return vec2(texel.x + mass, texel.y + centre * mass + moment);
}
