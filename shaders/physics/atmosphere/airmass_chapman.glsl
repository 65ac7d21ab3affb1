// Chapman-function airmass (requires airmass_common.glsl).
// Ch(x, χ) is the airmass from radius r = x·H to infinity along zenith angle χ ≤ 90°, relative to the
// vertical: ∫_r^∞ e^{−(r'−R)/H} ds = H·e^{−(r−R)/H}·Ch(r/H, χ) (S. Chapman 1931).
// A segment is integrated as a difference of half-line columns (airmassChapman below).

const int CHAPMAN_SCHUELER = 0;
const int CHAPMAN_HDRP = 1;

// Schüler's approximation (GPU Pro 3, 2012, "An approximation to the Chapman grazing-incidence function
// for atmospheric scattering"), as distributed with its sample code: Ch ≈ c/(c·cos χ + 1), c = √x.
real chapmanSchueler(real x, real cosZenith)
{
    real c = sqrt(x);
    return c / (c * cosZenith + real(1));
}

// The rational fit used by Unity HDRP's physically based sky (ChapmanUpperApprox, E. Heitz/Z. Dolgov's
// "Physically based sky" notes, eq. 43; stated to stay within 0.34%):
//   Ch ≈ cos χ/2 + 0.761643·(1 + x(2 − cos²χ)) / (x·cos χ + √(x·(1.47721 + 0.273828·x·cos²χ))).
real chapmanHdrp(real x, real cosZenith)
{
    real c = cosZenith;
    real n = real(0.761643) * ((real(1) + real(2) * x) - c * c * x);
    real d = c * x + sqrt(x * (real(1.47721) + real(0.273828) * (c * c * x)));
    return real(0.5) * c + n / d;
}

// Our design: the asymptotic expansion of Ch for large x to first order in 1/x (derivation in
// docs/airmass.md). With w the rise in scale heights, x·cos χ = ξ(0) and ξ(w) = √(x²cos²χ + 2xw + w²),
// Ch = ∫_0^∞ e^{−w} ξ'(w) dw; expanding ξ in w²/(2x) gives, with z = √(x/2)·cos χ,
//   Ch ≈ √(x/2)·√π·erfcx(z) + J₂(z)/(4·√(x/2)),   J₂ = ∫_0^∞ e^{−w} w²/√(w + z²) dw.
// The leading term is the exact-curvature parabola (√(πx/2) at 90°, 0.047% low at x = 796); the
// correction is 3/(8x) at 90° and vanishes for vertical rays. The neglected term is O(1/x²):
// 7e-6 at x = 127 (H = 50 km); the expansion is meant for x = r/H ≥ 50.
// Both erfcx and J₂ are t times a polynomial in t = 1/(1 + z/2) (airmassErfcxOverT, chapmanJ2OverT):
// one division, no exponential, no branch, finite for every z ≥ 0.

// J₂(z)/t with z = 2(1/t − 1): 1 + t·P(t) with P of degree 4, Chebyshev interpolation on t ∈ [0, 1] of
// the exact J₂ = √π·erfcx(z)·(z⁴ − z² + 3/4) − z³ + 3z/2 (ours). Relative error 0.10%, at most 4e-6 of Ch
// since the correction itself is at most 3/(8x). G(0) = 1 gives J₂ → 2/z, so that vertical rays keep
// Ch = 1 + O(x⁻²); G(1) ≈ Γ(5/2), the value at 90°.
real chapmanJ2OverT(real t)
{
    real t2 = t * t; // Estrin's scheme, as airmassErfcxOverT
    return real(1) + t * ((real(1.003354214) + t * real(0.4558560040)) + t2 * ((real(1.283027695) + t * real(-5.036607845))
                          + t2 * real(2.625062232)));
}

// Ch(r/H, χ) at a point of the ray at radius r and distance x from its closest approach (cos χ = |x|/r),
// given 1/H. With q = r/H (at least 1e-6, so that H ≫ r stays finite) and s = 1/√(q/2):
// √(q/2) = q·s/2 and z = √(q/2)·|x|/r = |x|·s/(2H).
real chapmanAsymptotic(real r, real x, real inverseH)
{
    real q = max(r * inverseH, real(1e-6));
    real s = inversesqrt(real(0.5) * q);
    real t = real(1) / (real(1) + real(0.25) * abs(x) * inverseH * s);   // 1/(1 + z/2)
    return t * (real(0.5) * q * s * sqrt(kPi) * airmassErfcxOverT(t) + real(0.25) * s * chapmanJ2OverT(t));
}

// The same at the closest approach (χ = 90°, z = 0, t = 1): the polynomials at t = 1 fold to constants.
real chapmanAsymptoticHorizontal(real r, real inverseH)
{
    real q = max(r * inverseH, real(1e-6));
    real s = inversesqrt(real(0.5) * q);
    return real(0.5) * q * s * sqrt(kPi) * airmassErfcxOverT(real(1)) + real(0.25) * s * chapmanJ2OverT(real(1));
}

// The published fits by kind (CHAPMAN_SCHUELER or CHAPMAN_HDRP).
real chapmanApproximation(real x, real cosZenith, int kind)
{
    if (kind == CHAPMAN_SCHUELER) return chapmanSchueler(x, cosZenith);
    return chapmanHdrp(x, cosZenith);
}

// Airmass of the monotone piece 0 ≤ xa ≤ xb at closest-approach distance y, whose ends lie at radii
// ra and rb (see the top of this file). rise = (rb − ra)/H is computed as (xb² − xa²)/((ra + rb)·H),
// free of cancellation. The exponent e^{−(ra−R)/H} is capped at e^{60} like airmassDensity.
real airmassChapmanPiece(real y, real xa, real xb, real ra, real rb, real H, real R, int kind)
{
    real rise = (xb - xa) * (xb + xa) / ((ra + rb) * H);
    if (!(rise > real(1))) return airmassGaussLegendre3(y, xa, xb, H, R);
    real cosZenithA = ra > real(0) ? xa / ra : real(1);
    real chapmanA = chapmanApproximation(ra / H, cosZenithA, kind);
    real chapmanB = chapmanApproximation(rb / H, xb / rb, kind);
    return H * exp(min((R - ra) / H, real(60))) * (chapmanA - exp(-rise) * chapmanB);
}

// Airmass of the segment [t0, t1] from Chapman functions of the given kind (signed), cut at the closest
// approach into monotone pieces; segments shorter than H take the safe form airmassShortSegment.
// Float geometry (airmassRayFrame); used by the published fits, whose own error (≥ 0.37%) dominates.
real airmassChapmanPieces(vec3 origin, vec3 direction, real t0, real t1, real H, real R, int kind)
{
    if (abs(t1 - t0) <= H) return airmassShortSegment(origin, direction, t0, t1, H, R);
    vec3 frame = airmassRayFrame(origin, direction, t0, t1);
    real y = frame.x;
    real lo = min(frame.y, frame.z);
    real hi = max(frame.y, frame.z);
    // The end radii straight from the end points: |o + t·d̂| is more accurate in float than √(x² + y²).
    vec3 d = direction / length(direction);
    real rLo = length(origin + min(t0, t1) * d);
    real rHi = length(origin + max(t0, t1) * d);
    real airmass;
    if (lo >= real(0)) {
        airmass = airmassChapmanPiece(y, lo, hi, rLo, rHi, H, R, kind);
    } else if (hi <= real(0)) {
        airmass = airmassChapmanPiece(y, -hi, -lo, rHi, rLo, H, R, kind);
    } else {
        airmass = airmassChapmanPiece(y, real(0), -lo, y, rLo, H, R, kind)
                + airmassChapmanPiece(y, real(0), hi, y, rHi, H, R, kind);
    }
    real segmentSign = frame.z < frame.y ? real(-1) : real(1);
    return segmentSign * airmass;
}

// The safe form takes over where the height varies by at most this many scale heights over the segment,
// and by at most the second where the segment crosses the closest approach.
const real AIRMASS_SAFE_VARIATION = real(0.08);
const real AIRMASS_SAFE_VARIATION_ACROSS = real(0.02);

// The default method's evaluation, for lengths scaled near 1 (airmassChapmanAsymptotic below): airmass
// of the segment [t0, t1] from the asymptotic Chapman function (signed). Branch-free: every quantity
// below is computed for every ray and the result is selected, because SIMD lanes (llvmpipe, GPU warps)
// that take different branches pay for all of them.
//
// With U(t) = e^{−h(t)/H}·Ch(r(t)/H, |x|/r) the upward half-line column from the point at |x| and
// T = e^{−h_t/H}·Ch(y/H, 90°) the column from the closest approach to infinity, the forward half-line
// column from t is U(t) after the closest approach (x ≥ 0) and 2T − U(t) before it, so for t_lo ≤ t_hi
//   I/H = ±U(t_lo) ∓ U(t_hi) + 2T·[x_lo < 0 ≤ x_hi]      (+U for x ≥ 0, −U for x < 0),
// one expression for segments after, before or across the closest approach (three Ch).
// Safe form: where the height varies by at most AIRMASS_SAFE_VARIATION·H over the segment (short
// segments, segments near the closest approach; AIRMASS_SAFE_VARIATION_ACROSS·H from the closest approach
// when the segment crosses it), that difference cancels; there the trapezoid rule with the end-derivative
// correction (Euler–Maclaurin) integrates the density ρ = e^{−h/H} over the width w:
//   I ≈ w/2·(ρ_lo + ρ_hi) + w²/12·(ρ'_lo − ρ'_hi),   ρ' = −ρ·(x/r)/H   (dh/dt = x/r),
// with error w⁵·ρ⁗/720, on each side of the closest approach (where ρ' = 0 and ρ is the tangent
// density) when the segment crosses it: no density beyond those of the Chapman form. All heights come
// from airmassSegmentGeometry, accurate from the exact float inputs.
real airmassChapmanAsymptoticUnit(vec3 origin, vec3 direction, real t0, real t1, real H, real R)
{
    real tLo = min(t0, t1);
    real tHi = max(t0, t1);
    AirmassSegmentGeometry g = airmassSegmentGeometry(origin, direction, tLo, tHi, R);
    if (!(g.directionLength > real(0))) return real(0);
    real inverseH = real(1) / H;
    real densityLo = exp(min(-g.hLo * inverseH, real(60)));
    real densityHi = exp(min(-g.hHi * inverseH, real(60)));

    // Chapman form.
    real upLo = densityLo * chapmanAsymptotic(g.rLo, g.xLo, inverseH);
    real upHi = densityHi * chapmanAsymptotic(g.rHi, g.xHi, inverseH);
    real densityTangent = exp(min(-g.hTangent * inverseH, real(60)));
    real tangent = densityTangent * chapmanAsymptoticHorizontal(g.yTangent, inverseH);
    bool across = g.xLo < real(0) && !(g.xHi < real(0));
    real columnLo = g.xLo < real(0) ? -upLo : upLo;
    real columnHi = g.xHi < real(0) ? -upHi : upHi;
    real chapman = H * (columnLo - columnHi + (across ? real(2) * tangent : real(0)));

    // Safe form.
    real lowest = across ? g.hTangent : min(g.hLo, g.hHi);
    real variation = (max(g.hLo, g.hHi) - lowest) * inverseH;
    bool safe = variation <= (across ? AIRMASS_SAFE_VARIATION_ACROSS : AIRMASS_SAFE_VARIATION);
    // dh/dt = x/r = cos χ, clamped because r = R + h cancels deep inside the planet.
    real slopeLo = clamp(g.xLo / max(g.rLo, real(1e-30)), real(-1), real(1));
    real slopeHi = clamp(g.xHi / max(g.rHi, real(1e-30)), real(-1), real(1));
    real widthA = across ? -g.xLo : tHi - tLo;
    real widthB = across ? g.xHi : real(0);
    real densityMiddle = across ? densityTangent : densityHi;
    // The rise of each end over its part in scale heights, w·(dh/dt)/H: at most about 2·0.08 where the
    // safe form is taken; clamped to 1 so that rounding deep inside the planet cannot overflow.
    real riseLo = clamp(widthA * inverseH * slopeLo, real(-1), real(1));
    real riseMiddle = across ? real(0) : clamp(widthA * inverseH * slopeHi, real(-1), real(1));
    real riseHi = clamp(widthB * inverseH * slopeHi, real(-1), real(1));
    real trapezoid = widthA * (real(0.5) * (densityLo + densityMiddle)
                               + real(0.0833333333333333333) * (densityMiddle * riseMiddle - densityLo * riseLo))
                   + widthB * (real(0.5) * (densityMiddle + densityHi) + real(0.0833333333333333333) * densityHi * riseHi);

    real airmass = safe ? trapezoid : chapman;
    return t1 < t0 ? -airmass : airmass;
}

// The default method for any finite input (docs/airmass.md, "Definitions", extreme inputs). I is homogeneous in the
// lengths, I(k·o, d, k·t0, k·t1, k·H, k·R) = k·I, and does not depend on |d|: both are scaled by powers of
// two, which is exact in float, so that the largest of |o_i|, R and H, and the largest |d_i|, lie in
// [1/2, 1) (up to 8 for lengths near float's maximum). Then no square above leaves float's range. After
// scaling, segment ends beyond 1e6 are clamped (farther out the height exceeds 1e6 − 2 ≥ 1e6·H: no air),
// H is at least 1e-20 (so that e^60·Ch stays below 1e36), and the result saturates at 1e38, which only a
// segment deep inside the planet (density capped at e^60) with lengths near float's maximum reaches.
// The exponent e of the power of two with x/2^e in [1/2, 1), for x ≥ 1e-30, and 2^e for e in
// [−125, 125], both from the float's bits (cheaper than log2, ldexp or libm calls; the same in C++ float
// and on the GPU).
#ifdef __cplusplus
int airmassBinaryExponent(real x)
{
    if constexpr (sizeof(real) == 4) {
        std::uint32_t bits;
        std::memcpy(&bits, &x, sizeof bits);
        return int((bits >> 23) & 255u) - 126;
    } else {
        std::uint64_t bits;
        std::memcpy(&bits, &x, sizeof bits);
        return int((bits >> 52) & 2047u) - 1022;
    }
}
real airmassPowerOfTwo(int e)
{
    real value;
    if constexpr (sizeof(real) == 4) {
        const std::uint32_t bits = std::uint32_t(e + 127) << 23;
        std::memcpy(&value, &bits, sizeof value);
    } else {
        const std::uint64_t bits = std::uint64_t(e + 1023) << 52;
        std::memcpy(&value, &bits, sizeof value);
    }
    return value;
}
#else
int airmassBinaryExponent(real x) { return ((floatBitsToInt(x) >> 23) & 255) - 126; }
real airmassPowerOfTwo(int e) { return intBitsToFloat((e + 127) << 23); }
#endif

real airmassChapmanAsymptotic(vec3 origin, vec3 direction, real t0, real t1, real H, real R)
{
    real largest = max(max(max(abs(origin.x), abs(origin.y)), max(abs(origin.z), R)), H);
    int exponent = min(airmassBinaryExponent(max(largest, real(1e-30))), 125); // 2^±125: normal floats
    real toUnit = airmassPowerOfTwo(-exponent);
    real largestDirection = max(max(abs(direction.x), abs(direction.y)), abs(direction.z));
    real toUnitDirection = airmassPowerOfTwo(-min(airmassBinaryExponent(max(largestDirection, real(1e-30))), 125));
    real airmass = airmassChapmanAsymptoticUnit(origin * toUnit, direction * toUnitDirection,
                                                clamp(t0 * toUnit, real(-1e6), real(1e6)),
                                                clamp(t1 * toUnit, real(-1e6), real(1e6)),
                                                max(H * toUnit, real(1e-20)), R * toUnit);
    real limit = real(1e38) * toUnit; // +inf when 2^exponent < 1, which clamps nothing
    return clamp(airmass, -limit, limit) * airmassPowerOfTwo(exponent);
}

// Airmass (km) of the half-line from a point at radius r to infinity, x the point's distance from the
// half-line's closest approach to the centre (x = o·d̂, negative while the half-line descends) and y that
// approach's radius (airmassRayFrame): the column U of the default method after the closest approach and
// 2T − U before it. Float geometry, meant for points near the planet (the sky's light paths): a radius
// rounded to float errs by half an ulp, 0.24 m near 6371 km, 3e-5 of H = 8 km. A ray that passes below
// the ground is not clipped (the caller tests its shadow).
real airmassHalfLine(real r, real x, real y, real H, real R)
{
    real inverseH = real(1) / H;
    real up = exp(min((R - r) * inverseH, real(60))) * chapmanAsymptotic(r, x, inverseH);
    real tangent = exp(min((R - y) * inverseH, real(60))) * chapmanAsymptoticHorizontal(y, inverseH);
    return H * (x < real(0) ? real(2) * tangent - up : up);
}

real airmassChapmanSchueler(vec3 origin, vec3 direction, real t0, real t1, real H, real R)
{
    return airmassChapmanPieces(origin, direction, t0, t1, H, R, CHAPMAN_SCHUELER);
}

real airmassChapmanHdrp(vec3 origin, vec3 direction, real t0, real t1, real H, real R)
{
    return airmassChapmanPieces(origin, direction, t0, t1, H, R, CHAPMAN_HDRP);
}
