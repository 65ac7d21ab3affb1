#pragma once
// Double-precision references for the airmass closed forms.
#include "physics/atmosphere/airmass.h"

namespace aurorawall::physics::atmosphere {

// ∫_{t0}^{t1} exp(−(|o + t·d̂| − R)/H) dt by adaptive Gauss–Kronrod (7/15), relative accuracy
// better than 1e-10. Same definitions as the closed forms (airmass.h): signed, zero direction → 0,
// transparent planet with the density capped at e^60.
double exactAirmass(const AirmassRay& ray);
double exactAirmass(glm::dvec3 origin, glm::dvec3 direction, double t0, double t1, double H, double R);

// The Chapman function Ch(x, χ) for χ ≤ 90°: airmass from radius x·H to infinity along zenith angle
// χ divided by H·e^{−(x·H − R)/H} — computed with exactAirmass.
double exactChapman(double x, double zenithAngle);

// e^x·K₁(x), the scaled modified Bessel function of the second kind, x > 0: std::cyl_bessel_k below
// x = 500, its asymptotic series (Abramowitz & Stegun 9.7.2) above, where e^x would overflow.
double scaledBesselK1(double x);

} // namespace aurorawall::physics::atmosphere
