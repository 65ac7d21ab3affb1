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
// Ch = ∫_0^∞ e^{−w} ξ'(w) dw; expanding ξ in w²/(2x) gives, with z = √(x/2)·cos χ and E = √π·erfcx(z),
//   Ch ≈ √(x/2)·E + J₂/(2√(2x)),   J₂ = ∫_0^∞ e^{−w} w²/√(w + z²) dw = E·(z⁴ − z² + 3/4) − z³ + 3z/2,
// and for z ≥ 8, where that sum cancels, J₂ = (2 − 3/z² + 9/z⁴ − 37.5/z⁶ + 196.875/z⁸)/z.
// The leading term is the exact-curvature parabola (√(πx/2) at 90°, 0.047% low at x = 796); the
// correction is 3/(8x) at 90° and vanishes for vertical rays. The neglected term is O(1/x²):
// 7e-6 at x = 127 (H = 50 km), about 4e-5 at x = 50; the expansion is meant for x = r/H ≥ 50.
// Both J₂ forms are evaluated and one is selected (no branch): each is finite for every z ≥ 0.
real chapmanAsymptotic(real x, real cosZenith)
{
    real halfX = real(0.5) * max(x, real(1e-6));
    real inverseHalfRoot = inversesqrt(halfX);             // 1/√(x/2); √(2x) = 2·√(x/2)
    real halfRoot = halfX * inverseHalfRoot;
    real z = halfRoot * cosZenith;
    real E = sqrt(AIRMASS_PI) * airmassErfcxPolynomial(z);
    real zNear = min(z, real(8));
    real zNear2 = zNear * zNear;
    real J2Near = E * ((zNear2 - real(1)) * zNear2 + real(0.75)) - zNear * (zNear2 - real(1.5));
    real inverseZ = real(1) / max(z, real(8));
    real inverseZ2 = inverseZ * inverseZ;
    real J2Far = (real(2) + inverseZ2 * (real(-3) + inverseZ2 * (real(9) + inverseZ2 * (real(-37.5)
                 + inverseZ2 * real(196.875))))) * inverseZ;
    real J2 = z < real(8) ? J2Near : J2Far;
    return halfRoot * E + real(0.25) * J2 * inverseHalfRoot;
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

// Ch at the horizon (χ = 90°), for the closest approach: the asymptotic form at z = 0 is
// √(πx/2)·(1 + 3/(8x)) (x·eˣK₁(x) to O(x⁻²)) and needs no erfcx.
real chapmanAsymptoticHorizontal(real x)
{
    real safeX = max(x, real(1e-6));
    return sqrt(real(0.5) * AIRMASS_PI * safeX) * (real(1) + real(0.375) / safeX);
}

// Density relative to the ground at t_ref + s, from a reference point of the ray at height hRef, radius
// rRef and distance xRef from the closest approach: r² − rRef² = s·(2·xRef + s), so
//   h = hRef + s·(2·xRef + s)/(rRef + r),
// which stays accurate in float however large rRef and xRef are (the increment is formed directly).
real airmassDensityAfter(real hRef, real rRef, real xRef, real s, real inverseH)
{
    real rise = s * (real(2) * xRef + s);
    real r = sqrt(max(rRef * rRef + rise, real(0)));
    real h = hRef + rise / max(rRef + r, real(1e-30));
    return exp(min(-h * inverseH, real(60)));
}

// The safe form switches at a variation of AIRMASS_SAFE_VARIATION scale heights over the segment.
const real AIRMASS_SAFE_VARIATION = real(0.25);

// The default method: airmass of the segment [t0, t1] from the asymptotic Chapman function (signed).
// Branch-free: every quantity below is computed for every ray and the result is selected, because SIMD
// lanes (llvmpipe, GPU warps) that take different branches pay for all of them.
//
// With U(t) = e^{−h(t)/H}·Ch(r(t)/H, |x|/r) the upward half-line column from the point at |x| and
// T = e^{−h_t/H}·Ch(y/H, 90°) the column from the closest approach to infinity, the forward half-line
// column from t is U(t) after the closest approach (x ≥ 0) and 2T − U(t) before it, so for t_lo ≤ t_hi
//   I/H = ±U(t_lo) ∓ U(t_hi) + 2T·[x_lo < 0 ≤ x_hi]      (+U for x ≥ 0, −U for x < 0),
// one expression for segments after, before or across the closest approach (two Ch, one Ch at 90°).
// Safe form: where the height varies by at most AIRMASS_SAFE_VARIATION·H over the segment (short
// segments, segments near the closest approach), the difference cancels; there the segment is integrated
// by 4-point Gauss–Lobatto in t (nodes at the ends and at ±1/√5 of the half-width, weights 1/6 and 5/6):
// the end densities are the Chapman form's, the inner heights are formed from the lower end
// (airmassDensityAfter). Its error peaks at the switch, 7.8e-5 across the closest approach.
// All heights come from airmassSegmentGeometry, accurate from the exact float inputs.
real airmassChapmanAsymptotic(vec3 origin, vec3 direction, real t0, real t1, real H, real R)
{
    // Beyond 1e18 km the squares below would leave float's range; no scale height reaches that far.
    real tLo = clamp(min(t0, t1), real(-1e18), real(1e18));
    real tHi = clamp(max(t0, t1), real(-1e18), real(1e18));
    AirmassSegmentGeometry g = airmassSegmentGeometry(origin, direction, tLo, tHi, R);
    if (!(g.directionLength > real(0))) return real(0);

    // Chapman form.
    real cosZenithLo = min(abs(g.xLo) / max(g.rLo, real(1e-30)), real(1));
    real cosZenithHi = min(abs(g.xHi) / max(g.rHi, real(1e-30)), real(1));
    real inverseH = real(1) / H;
    real densityLo = exp(min(-g.hLo * inverseH, real(60)));
    real densityHi = exp(min(-g.hHi * inverseH, real(60)));
    real upLo = densityLo * chapmanAsymptotic(g.rLo * inverseH, cosZenithLo);
    real upHi = densityHi * chapmanAsymptotic(g.rHi * inverseH, cosZenithHi);
    real tangent = exp(min(-g.hTangent * inverseH, real(60))) * chapmanAsymptoticHorizontal(g.yTangent * inverseH);
    bool across = g.xLo < real(0) && !(g.xHi < real(0));
    real columnLo = g.xLo < real(0) ? -upLo : upLo;
    real columnHi = g.xHi < real(0) ? -upHi : upHi;
    real chapman = H * (columnLo - columnHi + (across ? real(2) * tangent : real(0)));

    // Safe form.
    real lowest = across ? g.hTangent : min(g.hLo, g.hHi);
    real variation = (max(g.hLo, g.hHi) - lowest) * inverseH;
    real halfWidth = real(0.5) * (tHi - tLo);
    real offset = halfWidth * real(0.447213595499957939);   // √(1/5)
    real gauss = halfWidth * (real(0.166666666666666667) * (densityLo + densityHi)
                            + real(0.833333333333333333) * (airmassDensityAfter(g.hLo, g.rLo, g.xLo, halfWidth - offset, inverseH)
                                                          + airmassDensityAfter(g.hLo, g.rLo, g.xLo, halfWidth + offset, inverseH)));

    real airmass = variation <= AIRMASS_SAFE_VARIATION ? gauss : chapman;
    return t1 < t0 ? -airmass : airmass;
}

real airmassChapmanSchueler(vec3 origin, vec3 direction, real t0, real t1, real H, real R)
{
    return airmassChapmanPieces(origin, direction, t0, t1, H, R, CHAPMAN_SCHUELER);
}

real airmassChapmanHdrp(vec3 origin, vec3 direction, real t0, real t1, real H, real R)
{
    return airmassChapmanPieces(origin, direction, t0, t1, H, R, CHAPMAN_HDRP);
}
