// Lawlor's parabola airmass (requires airmass_common.glsl).
// Sources: O. S. Lawlor, "Raytracing a Planet's Atmosphere" (CS 481/681 lecture, UAF 2010)
// and Lawlor & Genetti, "Interactive Volume Rendering Aurora on the GPU", appendix A.
// The height along the ray, r(x) − R with r(x) = √(x² + y²), is replaced by a parabola A + C·x²
// through the radii r1 (the lowest radius the segment reaches) and r2 = r1 + 2H; then
//   I ≈ e^{−A/H}·√(π/(4k))·(erf(√k·x1) − erf(√k·x0)),   k = C/H.

// Parabola fit of Lawlor's lecture (steps 2–4), with k = 1/H, refHt = R, refDen = 1: returns (A, C).
vec2 lawlorParabola(real y, real xL, real xR, real H, real R)
{
    real ySqr = y * y;
    real r1Sqr;
    if (xL * xR < real(0)) {
        r1Sqr = ySqr;                                // span crosses the closest approach
    } else {
        r1Sqr = min(xL * xL + ySqr, xR * xR + ySqr); // the endpoint nearer the surface
    }
    real r1 = sqrt(r1Sqr);
    real r2 = r1 + real(2) * H;                      // "80% of atmosphere (at any height)"
    real x1Sqr = r1Sqr - ySqr;
    real x2Sqr = r2 * r2 - ySqr;
    real C = (r1 - r2) / (x1Sqr - x2Sqr);
    real A = r1 - x1Sqr * C - R;
    return vec2(A, C);
}

// Baseline, exactly as published in Lawlor's lecture with Winitzki's erf and `0.5·guts` erfc, including
// its closest-approach distance y = √(tc²a + tc·b + c) (clamped at 0 so that rounding cannot give a NaN).
// Published as |result|; here signed like every method: I(t1, t0) = −I(t0, t1).
real airmassLawlorWinitzki(vec3 start, vec3 direction, real tstart, real tend, real H, real R)
{
    real directionLength = length(direction);
    if (!(directionLength > real(0))) return real(0);
    vec3 dir = direction / directionLength;
    real k = real(1) / H;
    real a = dot(dir, dir);
    real b = real(2) * dot(dir, start);
    real c = dot(start, start);
    real tc = -b / (real(2) * a);
    real y = sqrt(max(tc * tc * a + tc * b + c, real(0)));
    real xL = tstart - tc;
    real xR = tend - tc;
    vec2 parabola = lawlorParabola(y, xL, xR, H, R);
    real sqrtKC = sqrt(k * parabola.y);
    real erfDel;
    if (xL * xR < real(0)) {
        erfDel = winitzkiErf(sqrtKC * xR) - winitzkiErf(sqrtKC * xL);
    } else {
        if (xL < real(0)) { xL = -xL; xR = -xR; }
        erfDel = winitzkiErfc(sqrtKC * xR) - winitzkiErfc(sqrtKC * xL);
    }
    real norm = sqrt(kPi) / real(2);
    real eScl = exp(-k * parabola.x);
    real segmentSign = tend < tstart ? real(-1) : real(1);
    return segmentSign * eScl * norm / sqrtKC * abs(erfDel);
}

// The same parabola with an accurate erfc. With s = √k·x and erfc = e^{−s²}·erfcx(s), every term is
// e^{−A/H − s²}·erfcx(s), its exponent combined before exp:
//   crossing (s0 < 0 < s1):  erf(s1) − erf(s0) = 2 − erfc(s1) − erfc(−s0),
//   same sign (0 ≤ s0 < s1): erf(s1) − erf(s0) = erfc(s0) − erfc(s1).
// The same-sign difference cancels when s1² − s0² < 1; there the safe form integrates e^{−A/H − s²}
// over [s0, s1] with 3-point Gauss–Legendre (error ~1e-6, continuous across the switch), and segments
// shorter than H take airmassShortSegment. Every density e^{−m − s²} is capped at e^60, as airmassDensity
// caps it deep inside the planet (from the centre, e^{R/H} overflowed and 2·inf − inf gave NaN).
real airmassLawlorErfcx(vec3 origin, vec3 direction, real t0, real t1, real H, real R)
{
    if (abs(t1 - t0) <= H) return airmassShortSegment(origin, direction, t0, t1, H, R);
    vec3 frame = airmassRayFrame(origin, direction, t0, t1);
    real lo = min(frame.y, frame.z);
    real hi = max(frame.y, frame.z);
    vec2 parabola = lawlorParabola(frame.x, lo, hi, H, R);
    real sqrtK = sqrt(parabola.y / H);
    real m = parabola.x / H;
    real s0 = sqrtK * lo;
    real s1 = sqrtK * hi;
    real erfIntegral;                                 // ∫_{s0}^{s1} e^{−m − s²} ds
    if (s0 < real(0) && s1 > real(0)) {
        erfIntegral = real(0.5) * sqrt(kPi) * (real(2) * exp(min(-m, real(60))) - exp(min(-m - s1 * s1, real(60))) * airmassErfcx(s1)
                                                       - exp(min(-m - s0 * s0, real(60))) * airmassErfcx(-s0));
    } else {
        real sa = min(abs(s0), abs(s1));
        real sb = max(abs(s0), abs(s1));
        if (sb * sb - sa * sa < real(1)) {
            real halfWidth = real(0.5) * (sb - sa);
            real middle = real(0.5) * (sa + sb);
            real offset = halfWidth * real(0.774596669241483377);
            erfIntegral = halfWidth * (real(0.555555555555555556) * exp(min(-m - (middle - offset) * (middle - offset), real(60)))
                                     + real(0.888888888888888889) * exp(min(-m - middle * middle, real(60)))
                                     + real(0.555555555555555556) * exp(min(-m - (middle + offset) * (middle + offset), real(60))));
        } else {
            erfIntegral = real(0.5) * sqrt(kPi) * (exp(min(-m - sa * sa, real(60))) * airmassErfcx(sa)
                                                           - exp(min(-m - sb * sb, real(60))) * airmassErfcx(sb));
        }
    }
    real segmentSign = frame.z < frame.y ? real(-1) : real(1);
    return segmentSign * erfIntegral / sqrtK;
}
