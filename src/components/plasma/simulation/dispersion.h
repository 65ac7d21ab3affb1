#pragma once
// What linear theory (and the leapfrog's own dispersion) predicts for the verification cases.
// Frequencies and rates in units of the electron plasma frequency ω_p.
#include <complex>

namespace aurorawall::plasma {

// The cold plasma oscillation under the leapfrog: sin(ω Δt/2) = ω_p Δt/2 (Birdsall & Langdon 1991,
// §4-2), so ω/ω_p = 2·asin(ω_pΔt/2)/(ω_pΔt). For 0 < ω_pΔt < 2 (std::domain_error otherwise).
double leapfrogPlasmaFrequency(double plasmaFrequencyTimesDt);

// The Boris rotation per step in a pure magnetic field: 2·atan(ω_cΔt/2) (rad).
double borisRotationPerStep(double cyclotronFrequencyTimesDt);

// The growth rate γ/ω_p of the cold symmetric two-stream instability (two beams of ±v₀, each of half
// the density): the unstable root of 1 = (ω_p²/2)[1/(ω − k v₀)² + 1/(ω + k v₀)²], i.e.
//   ω² = (k v₀)² + ω_p²/2 − (ω_p/√2)·√(ω_p²/2 + 4 (k v₀)²),
// γ = √(−ω²) where ω² < 0 (k v₀ < ω_p), else 0. Its maximum, 1/(2√2), is at k v₀ = √(3/8) ω_p.
double twoStreamGrowthRate(double kv0OverPlasmaFrequency);

// The plasma dispersion function Z(ζ) (Fried & Conte 1961), analytically continued to Im ζ ≤ 0 as
// Landau's contour requires: Z(ζ) = i√π exp(−ζ²) − 2 F(ζ), F Dawson's integral. For |ζ| < 4 by the
// power series of F (all ζ; its cancellation costs at most exp(|ζ|²) of rounding), beyond by the
// continued fraction of the Faddeeva function for Im ζ ≥ 0 (Gautschi 1970) and Z(ζ) = 2i√π exp(−ζ²) − Z(−ζ)
// below the real axis.
std::complex<double> plasmaDispersionZ(std::complex<double> zeta);

// The least-damped Langmuir wave of a Maxwellian plasma: the root ω/ω_p of the kinetic dispersion
// relation 1 + (1 + ζ Z(ζ))/(k λ_D)² = 0, ζ = ω/(√2 k v_th), by Newton's method from the
// Bohm–Gross frequency (Z' = −2(1 + ζ Z)). Im ω < 0 is the Landau damping rate of the field amplitude.
std::complex<double> landauRoot(double kDebyeLength);

} // namespace aurorawall::plasma
