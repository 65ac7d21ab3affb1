#pragma once
// What linear theory (and the leapfrog's own dispersion) predicts for the verification cases.
// Frequencies and rates in units of the electron plasma frequency ω_p.
#include <complex>

namespace aurorawall::components::plasma::simulation {

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

// The diocotron growth rate γ/ω_D (ω_D = e n_b/(ε₀B)) of mode k of a uniform electron strip of
// thickness 2a in the guiding-centre (E×B drift) limit ω_p ≪ ω_c, in a box periodic across with
// width L and a uniform neutralising background over the whole box (mean density n_b·f, f = 2a/L).
// The drift flow U(y) = E_y/B is piecewise linear with kinks of jump ω_D at the strip's edges, so
// Rayleigh's edge-wave analysis (Drazin & Reid, Hydrodynamic Stability (2004), §23; Levy 1965) with
// the periodic Green's function g(y) = cosh(k(|y| − L/2))/sinh(kL/2) of ψ'' − k²ψ gives
//   γ/ω_D = ½ √( g(2a)² − (g(0) − 2ka(1 − f))² ),
// 0 where the root is negative (stable). For L → ∞ this is Levy's ½ √(e^{−4ka} − (1 − 2ka)²), whose
// maximum 0.2012 is at ka ≈ 0.40. std::domain_error unless 0 < 2a < L and k > 0.
double diocotronGrowthRate(double kHalfThickness, double kWidth);

} // namespace aurorawall::components::plasma::simulation
