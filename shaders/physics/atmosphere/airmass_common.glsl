// Shared pieces of the airmass closed forms (see docs/airmass.md).
// One text for GLSL and C++ (src/common/glsl.h): `real` is float on the GPU, float or double on the CPU.
// Needs physics/constants.glsl.
//
// Airmass of a ray segment through an exponential atmosphere on a sphere of radius R (km),
// scale height H (km):   I = ∫_{t0}^{t1} exp(−(|o + t·d̂| − R)/H) dt   (km, signed: I(t1,t0) = −I(t0,t1)).


// C++ has no `precise` qualifier; GLSL's `precise` forbids the compiler to reassociate or contract the
// marked arithmetic, which the error-free transformations below rely on (the C++ side is compiled with
// -ffp-contract=off, src/physics/atmosphere/CMakeLists.txt). Veltkamp's splitter 2^⌈p/2⌉ + 1 for p mantissa bits:
// 4097 in float, 134217729 in double.
#ifdef __cplusplus
#define precise
const real AIRMASS_SPLITTER = real((1L << ((std::numeric_limits<real>::digits + 1) / 2)) + 1);
#else
const real AIRMASS_SPLITTER = real(4097);
#endif

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

// The same t = 1/(1 + z/2), with exp(P(t)) replaced by one polynomial F(t) = erfcx(z)/t of degree 8
// (Chebyshev interpolation on t ∈ [0, 1] of the exact erfcx, ours): relative error 1.0e-6 and no
// exponential. F(0) = 1/(2√π) gives erfcx → 1/(√π z). For the default method: erfcx(z) = t·F(t).
real airmassErfcxOverT(real t)
{
    // Estrin's scheme: independent pairs, combined with t², t⁴ and t⁸ (a shorter dependency chain than Horner's).
    real t2 = t * t;
    real t4 = t2 * t2;
    real low = (real(2.820944907e-01) + t * real(2.821437503e-01)) + t2 * (real(2.455030781e-01) + t * real(1.903893512e-01));
    real high = (real(8.622661503e-03) + t * real(2.188417503e-01)) + t2 * (real(-4.292615699e-01) + t * real(2.540236004e-01));
    return low + t4 * (high + t4 * real(-5.235712482e-02));
}

// Winitzki's erf approximation, exactly as Lawlor publishes it ("Raytracing a Planet's Atmosphere", "erf on the GPU"):
// erf(x) ≈ sign(x)·√(1 − exp(−x²·(4/π + a·x²)/(1 + a·x²))), a = 8(π − 3)/(3π(4 − π)) ≈ 0.140012.
real winitzkiErfGuts(real x)
{
    real a = real(8) * (kPi - real(3)) / (real(3) * kPi * (real(4) - kPi));
    real x2 = x * x;
    return exp(-x2 * (real(4) / kPi + a * x2) / (real(1) + a * x2));
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

// ---- Heights along the ray without cancellation (the default method's geometry) ----
// Near 6771 km one float ulp is 0.49 m, and near 42157 km (geostationary orbit) 3.9 m, so |o + t·d̂| − R
// in float loses what a 1 km scale height needs (1e-3 of H is 1 m). The inputs themselves are exact floats, so
// the heights below are computed from them with error-free transformations (TwoSum, Dekker's product,
// and Ogita–Rump–Oishi's Dot2, SIAM J. Sci. Comput. 26, 1955 (2005)): r² − R² is formed in twice the
// float precision and only then divided, h = (r² − R²)/(r + R), which keeps h to float's relative precision.

// a + b = s + e exactly (Knuth's TwoSum); returns (s, e).
vec2 airmassTwoSum(real a, real b)
{
    precise real s = a + b;
    precise real bVirtual = s - a;
    precise real e = (a - (s - bVirtual)) + (b - bVirtual);
    return vec2(s, e);
}

// Veltkamp's split: a = high + low exactly, each half with at most half the mantissa bits, so that
// products of halves are exact. Returns high (low = a − high).
vec3 airmassSplitHigh(vec3 a)
{
    precise vec3 c = AIRMASS_SPLITTER * a;
    precise vec3 high = c - (c - a);
    return high;
}

// a·b = p + e exactly (Dekker's product; no fma, which llvmpipe does not fuse), from the splits of a
// and b; returns e for p = a·b rounded. Exact unless a·b under- or overflows (|a|, |b| < 1e18 here).
vec3 airmassProductError(vec3 p, vec3 aHigh, vec3 aLow, vec3 bHigh, vec3 bLow)
{
    precise vec3 e = ((aHigh * bHigh - p) + aHigh * bLow + aLow * bHigh) + aLow * bLow;
    return e;
}

// a·b = p + e exactly for scalars; returns (p, e).
vec2 airmassTwoProduct(real a, real b)
{
    vec3 high = airmassSplitHigh(vec3(a, b, real(0)));
    precise vec3 low = vec3(a, b, real(0)) - high;
    precise real p = a * b;
    return vec2(p, airmassProductError(vec3(p), vec3(high.x), vec3(low.x), vec3(high.y), vec3(low.y)).x);
}

// a·b of two 3-vectors as hi + lo, as accurate as if summed in twice the precision (Dot2), from the
// vectors' splits.
vec2 airmassDot2(vec3 a, vec3 aHigh, vec3 aLow, vec3 b, vec3 bHigh, vec3 bLow)
{
    precise vec3 p = a * b;
    vec3 e = airmassProductError(p, aHigh, aLow, bHigh, bLow);
    vec2 sxy = airmassTwoSum(p.x, p.y);
    vec2 s = airmassTwoSum(sxy.x, p.z);
    precise real lo = ((e.x + e.y) + (e.z + sxy.y)) + s.y;
    return vec2(s.x, lo);
}

// (a.x + a.y) + (b.x + b.y) as hi + lo.
vec2 airmassAdd2(vec2 a, vec2 b)
{
    vec2 s = airmassTwoSum(a.x, b.x);
    precise real lo = s.y + (a.y + b.y);
    return vec2(s.x, lo);
}

// Height above R of a point whose radius r satisfies r² − R² = excess.x + excess.y (hi + lo):
// h = (r² − R²)/(r + R), accurate to float's relative precision however close r is to R.
real airmassHeightFromExcess(vec2 excess, real R)
{
    real excessSum = excess.x + excess.y;
    real r = sqrt(max(R * R + excessSum, real(0)));
    return excessSum / max(r + R, real(1e-30));
}

// The segment t ∈ [tLo, tHi] of the ray o + t·d̂ in the plane through the planet's centre.
// b = o·d̂, the closest approach to the centre is at t_c = −b (radius y, height hTangent), and
// x = t − t_c = t + b is the signed distance from it (x < 0 before it). Then
//   y² − R² = (|o|² − R²) − b²,   r(t)² − R² = (y² − R²) + x²,
// each summed in twice the precision from the exact float inputs (|o|², o·d and |d|² by Dot2, b and
// |d| with one correction step each), and h = (r² − R²)/(r + R).
struct AirmassSegmentGeometry {
    real directionLength; // |d|; 0 for a zero direction (no ray)
    real xLo;             // tLo + b
    real xHi;
    real hLo;             // heights above R of the ends
    real hHi;
    real rLo;             // radii of the ends (float; for cos χ and denominators)
    real rHi;
    real hTangent;        // y − R
    real yTangent;        // y, the closest approach's radius
};

// r² − R² at distance x = t + b (a pair) from the closest approach, given y² − R².
vec2 airmassExcessAt(real t, vec2 b, vec2 tangentExcess)
{
    vec2 x = airmassTwoSum(t, b.x);
    precise real xLow = x.y + b.y;
    vec2 xSquared = airmassTwoProduct(x.x, x.x);
    precise real xSquaredLow = xSquared.y + real(2) * x.x * xLow;
    return airmassAdd2(tangentExcess, vec2(xSquared.x, xSquaredLow));
}

AirmassSegmentGeometry airmassSegmentGeometry(vec3 origin, vec3 direction, real tLo, real tHi, real R)
{
    AirmassSegmentGeometry g;
    vec3 oHigh = airmassSplitHigh(origin);
    precise vec3 oLow = origin - oHigh;
    vec3 dHigh = airmassSplitHigh(direction);
    precise vec3 dLow = direction - dHigh;
    vec2 dd = airmassDot2(direction, dHigh, dLow, direction, dHigh, dLow);
    vec2 od = airmassDot2(origin, oHigh, oLow, direction, dHigh, dLow);
    vec2 oo = airmassDot2(origin, oHigh, oLow, origin, oHigh, oLow);
    // |d| = L + lLow, then b = (o·d)/|d| = bHigh + bLow.
    // (One reciprocal: the corrections take up whatever the rounded quotients miss.)
    real L = sqrt(dd.x);
    real inverseL = real(1) / max(L, real(1e-30));
    vec2 lSquared = airmassTwoProduct(L, L);
    precise real lLow = ((dd.x - lSquared.x) - lSquared.y + dd.y) * (real(0.5) * inverseL);
    real bHigh = od.x * inverseL;
    vec2 bL = airmassTwoProduct(bHigh, L);
    precise real bLow = (((od.x - bL.x) - bL.y + od.y) - bHigh * lLow) * inverseL;
    // y² − R² = |o|² − R² − b²
    vec2 rSquared = airmassTwoProduct(R, R);
    vec2 bSquared = airmassTwoProduct(bHigh, bHigh);
    precise real bSquaredLow = bSquared.y + real(2) * bHigh * bLow;
    vec2 tangentExcess = airmassAdd2(airmassAdd2(oo, vec2(-rSquared.x, -rSquared.y)), vec2(-bSquared.x, -bSquaredLow));
    vec2 b = vec2(bHigh, bLow);
    g.directionLength = L;
    g.xLo = (tLo + bHigh) + bLow;
    g.xHi = (tHi + bHigh) + bLow;
    g.hLo = airmassHeightFromExcess(airmassExcessAt(tLo, b, tangentExcess), R);
    g.hHi = airmassHeightFromExcess(airmassExcessAt(tHi, b, tangentExcess), R);
    g.rLo = R + g.hLo;
    g.rHi = R + g.hHi;
    g.hTangent = airmassHeightFromExcess(tangentExcess, R);
    g.yTangent = max(R + g.hTangent, real(0));
    return g;
}
