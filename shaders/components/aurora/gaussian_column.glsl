// The smooth curtain's Gaussian profile exp(−x²/2) integrated across an interval, for integrating a
// ray step across a curtain in closed form (aurora_curtains.glsl). One text for GLSL and C++
// (src/common/glsl.h): `real` is float on the GPU, float or double on the CPU.

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
