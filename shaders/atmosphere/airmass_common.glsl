// Shared pieces of the airmass closed forms (see docs/airmass.md).
// One text for GLSL and C++ (src/common/glsl.h): `real` is float on the GPU, float or double on the CPU.
//
// Airmass of a ray segment through an exponential atmosphere on a sphere of radius R (km),
// scale height H (km):   I = ∫_{t0}^{t1} exp(−(|o + t·d̂| − R)/H) dt   (km, signed: I(t1,t0) = −I(t0,t1)).

const real AIRMASS_PI = real(3.14159265358979323846);

// The ray in its own plane through the planet's centre. With d̂ = d/|d|, the closest approach to the
// centre lies at t_c = −o·d̂ at distance y = |o|·sin∠(o, d̂); x = t − t_c is the distance from it, so
// the radius along the ray is r(x) = √(x² + y²). Returns (y, x0, x1).
// sin∠(ô, d̂) = |ô − d̂|·|ô + d̂|/2 (Kahan's well-conditioned angle between unit vectors) keeps y
// accurate in float for grazing rays, where √(|o|² − (o·d̂)²) would cancel catastrophically.
// A zero direction has no ray: (|o|, 0, 0), a zero-length segment, so every method returns 0.
vec3 airmassRayFrame(vec3 origin, vec3 direction, real t0, real t1)
{
    real directionLength = length(direction);
    real originDistance = length(origin);
    if (!(directionLength > real(0))) return vec3(originDistance, real(0), real(0));
    vec3 d = direction / directionLength;
    vec3 up = originDistance > real(0) ? origin / originDistance : d;
    real y = originDistance * length(up - d) * length(up + d) * real(0.5);
    real tClosest = -dot(origin, d);
    return vec3(y, t0 - tClosest, t1 - tClosest);
}

// Density relative to the ground, exp(−(r − R)/H), at distance x from the closest approach.
// The planet is transparent (the renderer clips segments at the ground itself); more than 60 scale
// heights below the surface the density stays at e^60, so that no finite input overflows.
real airmassDensity(real y, real x, real H, real R)
{
    return exp(min((R - sqrt(x * x + y * y)) / H, real(60)));
}

// 3-point Gauss–Legendre rule for ∫_{xa}^{xb} exp(−(r(x) − R)/H) dx (Abramowitz & Stegun 25.4.29).
// The safe form for short pieces: exact to ~1e-6 when the exponent varies by at most 1 over the piece.
real airmassGaussLegendre3(real y, real xa, real xb, real H, real R)
{
    real halfWidth = real(0.5) * (xb - xa);
    real middle = real(0.5) * (xa + xb);
    real offset = halfWidth * real(0.774596669241483377);   // √(3/5)
    return halfWidth * (real(0.555555555555555556) * airmassDensity(y, middle - offset, H, R)
                      + real(0.888888888888888889) * airmassDensity(y, middle, H, R)
                      + real(0.555555555555555556) * airmassDensity(y, middle + offset, H, R));
}

// Safe form for a segment shorter than one scale height (the exponent varies by at most 1): 3-point
// Gauss–Legendre in t with the radius |o + t·d̂| taken directly. Positions relative to the closest
// approach (x = t − t_c) cannot resolve such a segment in float once |t_c| ≫ |t1 − t0|.
// Signed like the segment; a zero direction gives 0.
real airmassShortSegment(vec3 origin, vec3 direction, real t0, real t1, real H, real R)
{
    real directionLength = length(direction);
    if (!(directionLength > real(0))) return real(0);
    vec3 d = direction / directionLength;
    real halfWidth = real(0.5) * (t1 - t0);
    real middle = real(0.5) * (t0 + t1);
    real offset = halfWidth * real(0.774596669241483377);
    return halfWidth * (real(0.555555555555555556) * exp(min((R - length(origin + (middle - offset) * d)) / H, real(60)))
                      + real(0.888888888888888889) * exp(min((R - length(origin + middle * d)) / H, real(60)))
                      + real(0.555555555555555556) * exp(min((R - length(origin + (middle + offset) * d)) / H, real(60))));
}

// Scaled complementary error function erfcx(z) = e^{z²}·erfc(z) for z ≥ 0.
// Numerical Recipes in C (2nd ed., §6.2, erfcc): erfc(z) = t·exp(−z² + P(t)), t = 1/(1 + z/2),
// fractional error < 1.2e-7 for all z ≥ 0; without its exp(−z²) factor it is erfcx, which stays
// finite and accurate for any z (→ 1/(√π z)) and lets callers combine exponents before exp.
real airmassErfcx(real z)
{
    real t = real(1) / (real(1) + real(0.5) * z);
    real p = real(-1.26551223) + t * (real(1.00002368) + t * (real(0.37409196) + t * (real(0.09678418)
           + t * (real(-0.18628806) + t * (real(0.27886807) + t * (real(-1.13520398) + t * (real(1.48851587)
           + t * (real(-0.82215223) + t * real(0.17087277)))))))));
    return t * exp(p);
}

// Winitzki's erf approximation, exactly as Lawlor publishes it (seed 001, "erf on the GPU"):
// erf(x) ≈ sign(x)·√(1 − exp(−x²·(4/π + a·x²)/(1 + a·x²))), a = 8(π − 3)/(3π(4 − π)) ≈ 0.140012.
real winitzkiErfGuts(real x)
{
    real a = real(8) * (AIRMASS_PI - real(3)) / (real(3) * AIRMASS_PI * (real(4) - AIRMASS_PI));
    real x2 = x * x;
    return exp(-x2 * (real(4) / AIRMASS_PI + a * x2) / (real(1) + a * x2));
}

real winitzkiErf(real x)
{
    real s = real(1);
    if (x < real(0)) s = real(-1);
    return s * sqrt(real(1) - winitzkiErfGuts(x));
}

// Lawlor's erfc: 1 − erf, but 0.5·guts for x > 3 (√(1 − e) ≈ 1 − e/2), as published.
real winitzkiErfc(real x)
{
    if (x > real(3)) return real(0.5) * winitzkiErfGuts(x);
    return real(1) - winitzkiErf(x);
}
