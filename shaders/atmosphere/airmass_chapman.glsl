// Chapman-function airmass (requires airmass_common.glsl).
// Ch(x, χ) is the airmass from radius r = x·H to infinity along zenith angle χ ≤ 90°, relative to the
// vertical: ∫_r^∞ e^{−(r'−R)/H} ds = H·e^{−(r−R)/H}·Ch(r/H, χ) (S. Chapman 1931).
// A segment is cut at the closest approach into monotone pieces; on a piece from xa to xb (0 ≤ xa ≤ xb,
// r rising from ra to rb) the airmass is the difference of two half-line airmasses,
//   I = H·e^{−(ra−R)/H}·(Ch(ra/H, χa) − e^{−(rb−ra)/H}·Ch(rb/H, χb)),   cos χ = x/r.
// The difference cancels when the piece rises by less than one scale height; there the safe form is
// 3-point Gauss–Legendre on the piece (both sides agree to ~1e-5 at the switch).

const int CHAPMAN_SCHUELER = 0;
const int CHAPMAN_HDRP = 1;
const int CHAPMAN_ASYMPTOTIC = 2;

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

// Huestis' exact integral (J. Quant. Spectrosc. Radiat. Transfer 69, 709 (2001), eq. 9), χ ≤ 90°:
//   Ch(x, χ) = 1 + x·sin χ ∫_0^χ exp(x·(1 − sin χ/sin θ)) / (1 + cos θ) dθ,
// by 8-point Gauss–Legendre over θ ∈ [χ − w, χ], w = min(χ, 6/√x): below χ − w the integrand is
// under e^{−x·w²/2} = e^{−18}. The safe form of chapmanAsymptotic below x = 50.
real huestisIntegrand(real x, real sinZenith, real theta)
{
    return exp(x * (real(1) - sinZenith / sin(theta))) / (real(1) + cos(theta));
}

real chapmanHuestis(real x, real cosZenith)
{
    real sinZenith = sqrt(max(real(1) - cosZenith * cosZenith, real(0)));
    real zenith = acos(clamp(cosZenith, real(0), real(1)));
    if (!(zenith > real(0))) return real(1);   // vertical: Ch = 1 (and no node at θ = 0)
    real halfZenith = real(0.5) * min(zenith, real(6) / sqrt(x));
    real middle = zenith - halfZenith;
    real u1 = halfZenith * real(0.183434642495649805);
    real u2 = halfZenith * real(0.525532409916328986);
    real u3 = halfZenith * real(0.796666477413626740);
    real u4 = halfZenith * real(0.960289856497536232);
    real sum = real(0.362683783378361983) * (huestisIntegrand(x, sinZenith, middle - u1) + huestisIntegrand(x, sinZenith, middle + u1))
             + real(0.313706645877887287) * (huestisIntegrand(x, sinZenith, middle - u2) + huestisIntegrand(x, sinZenith, middle + u2))
             + real(0.222381034453374471) * (huestisIntegrand(x, sinZenith, middle - u3) + huestisIntegrand(x, sinZenith, middle + u3))
             + real(0.101228536290376259) * (huestisIntegrand(x, sinZenith, middle - u4) + huestisIntegrand(x, sinZenith, middle + u4));
    return real(1) + x * sinZenith * halfZenith * sum;
}

// Our design: the asymptotic expansion of Ch for large x to first order in 1/x (derivation in
// docs/airmass.md). With w the rise in scale heights, x·cos χ = ξ(0) and ξ(w) = √(x²cos²χ + 2xw + w²),
// Ch = ∫_0^∞ e^{−w} ξ'(w) dw; expanding ξ in w²/(2x) gives, with z = √(x/2)·cos χ and E = √π·erfcx(z),
//   Ch ≈ √(x/2)·E + J₂/(2√(2x)),   J₂ = ∫_0^∞ e^{−w} w²/√(w + z²) dw = E·(z⁴ − z² + 3/4) − z³ + 3z/2,
// and for z ≥ 8, where that sum cancels, J₂ = (2 − 3/z² + 9/z⁴ − 37.5/z⁶ + 196.875/z⁸)/z.
// The leading term is the exact-curvature parabola (√(πx/2) at 90°, 0.047% low at x = 796); the
// correction is 3/(8x) at 90° and vanishes for vertical rays. The neglected term is O(1/x²):
// 7e-6 at x = 127 (H = 50 km). Below x = 50 it switches to Huestis' integral.
real chapmanAsymptotic(real x, real cosZenith)
{
    if (x < real(50)) return chapmanHuestis(x, cosZenith);
    real z = sqrt(real(0.5) * x) * cosZenith;
    real E = sqrt(AIRMASS_PI) * airmassErfcx(z);
    real z2 = z * z;
    real J2;
    if (z < real(8)) {
        J2 = E * ((z2 - real(1)) * z2 + real(0.75)) - z * (z2 - real(1.5));
    } else {
        real inverseZ2 = real(1) / z2;
        J2 = (real(2) + inverseZ2 * (real(-3) + inverseZ2 * (real(9) + inverseZ2 * (real(-37.5)
             + inverseZ2 * real(196.875))))) / z;
    }
    return sqrt(real(0.5) * x) * E + J2 / (real(2) * sqrt(real(2) * x));
}

real chapmanApproximation(real x, real cosZenith, int kind)
{
    if (kind == CHAPMAN_SCHUELER) return chapmanSchueler(x, cosZenith);
    if (kind == CHAPMAN_HDRP) return chapmanHdrp(x, cosZenith);
    return chapmanAsymptotic(x, cosZenith);
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

// Airmass of the segment [t0, t1] from Chapman functions of the given kind (signed); segments shorter
// than H take the safe form airmassShortSegment.
real airmassChapman(vec3 origin, vec3 direction, real t0, real t1, real H, real R, int kind)
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

real airmassChapmanSchueler(vec3 origin, vec3 direction, real t0, real t1, real H, real R)
{
    return airmassChapman(origin, direction, t0, t1, H, R, CHAPMAN_SCHUELER);
}

real airmassChapmanHdrp(vec3 origin, vec3 direction, real t0, real t1, real H, real R)
{
    return airmassChapman(origin, direction, t0, t1, H, R, CHAPMAN_HDRP);
}

real airmassChapmanAsymptotic(vec3 origin, vec3 direction, real t0, real t1, real H, real R)
{
    return airmassChapman(origin, direction, t0, t1, H, R, CHAPMAN_ASYMPTOTIC);
}
