// A curtain's profile integrated across an interval, for integrating a ray step across a curtain
// in closed form (aurora_curtains.glsl): the smooth curtain's Gaussian exp(−x²/2), and the running
// integrals of tabulated flux frames. One text for GLSL and C++ (src/common/glsl.h): `real` is
// float on the GPU, float or double on the CPU.

// erfc(x) for x ≥ 0 by the Chebyshev fit of Press et al., "Numerical Recipes" (2nd ed., 1992, §6.2,
// erfcc): relative error below 1.2e-7 for every x ≥ 0, and no cancellation in the tail.
real erfcNonNegative(real x)
{
    real t = real(1.0) / (real(1.0) + real(0.5) * x);
    real p = real(-0.82215223) + t * real(0.17087277);
    p = real(1.48851587) + t * p;
    p = real(-1.13520398) + t * p;
    p = real(0.27886807) + t * p;
    p = real(-0.18628806) + t * p;
    p = real(0.09678418) + t * p;
    p = real(0.37409196) + t * p;
    p = real(1.00002368) + t * p;
    return t * exp(-x * x - real(1.26551223) + t * p);
}

// ∫ exp(−x²/2) dx from a to b (either order: negative when b < a). Written with erfc of
// non-negative arguments only, so that two tails are subtracted, never two values near 1
// (√(π/2) = 1.2533141373155003).
real gaussianMass(real a, real b)
{
    real lo = min(a, b);
    real hi = max(a, b);
    real s = real(0.70710678118654752); // 1/√2
    real mass;
    if (lo >= real(0.0))
        mass = erfcNonNegative(lo * s) - erfcNonNegative(hi * s);
    else if (hi <= real(0.0))
        mass = erfcNonNegative(-hi * s) - erfcNonNegative(-lo * s);
    else
        mass = real(2.0) - erfcNonNegative(-lo * s) - erfcNonNegative(hi * s);
    return (b < a ? real(-1.0) : real(1.0)) * real(1.2533141373155003) * mass;
}

// ∫ x exp(−x²/2) dx from a to b: exp(−a²/2) − exp(−b²/2).
real gaussianMoment(real a, real b)
{
    return exp(real(-0.5) * a * a) - exp(real(-0.5) * b * b);
}

// The running integrals C(a) = ∫_{−w/2}^{a} F da' and M(a) = ∫_{−w/2}^{a} a' F da' of a flux F that is
// linear between cell centres (src/components/fluid_detail/simulation/flux_columns.h), from the
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
