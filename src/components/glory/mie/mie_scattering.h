#pragma once
// What a sphere does to light, from its Mie coefficients: efficiencies, asymmetry parameter and the
// scattering amplitudes S1, S2 (Bohren & Huffman 1983, §4.4–4.5; Wiscombe 1980, Appl. Opt. 19, 1505),
// in the sign convention of mie_coefficients.h (m = n − ik).
#include "components/glory/mie/mie_coefficients.h"

#include <complex>
#include <vector>

namespace aurorawall::components::glory::mie {

struct Efficiencies {
    double extinction = 0.0; // Qext = (2/x²) Σ (2n+1) Re(aₙ + bₙ)
    double scattering = 0.0; // Qsca = (2/x²) Σ (2n+1) (|aₙ|² + |bₙ|²)
    double backscatter = 0.0; // Qback = 4 |S1(180°)|²/x² (Bohren & Huffman's radar backscattering efficiency)
    double asymmetry = 0.0;  // g = ⟨cos θ⟩ = (4/(x² Qsca)) Σ [n(n+2)/(n+1) Re(aₙa*ₙ₊₁ + bₙb*ₙ₊₁) + (2n+1)/(n(n+1)) Re(aₙb*ₙ)]
    double absorption() const { return extinction - scattering; }
};

Efficiencies efficiencies(const MieCoefficients& c);

// The amplitudes at one scattering angle: the field scattered perpendicular (S1) and parallel (S2) to
// the scattering plane.
struct Amplitudes {
    std::complex<double> s1, s2;
};

// S1 = Σ (2n+1)/(n(n+1)) (aₙπₙ + bₙτₙ), S2 = Σ (2n+1)/(n(n+1)) (aₙτₙ + bₙπₙ), with the angular
// functions by upward recurrence in μ = cos θ (Bohren & Huffman eq. 4.47): π₀ = 0, π₁ = 1,
// πₙ = (2n−1)/(n−1) μ πₙ₋₁ − n/(n−1) πₙ₋₂, τₙ = n μ πₙ − (n+1) πₙ₋₁. Exact at θ = 0° and 180° too
// (μ = ±1 exactly there). One entry per angle, in radians.
std::vector<Amplitudes> amplitudes(const MieCoefficients& c, const std::vector<double>& anglesRad);
Amplitudes amplitudesAtCosine(const MieCoefficients& c, double mu);

// The closed forms at the two exact angles (Bohren & Huffman §4.4.4, with πₙ(±1), τₙ(±1)):
// S1(0°) = S2(0°) = ½ Σ (2n+1)(aₙ + bₙ); S1(180°) = −S2(180°) = ½ Σ (2n+1)(−1)ⁿ⁺¹(aₙ − bₙ).
std::complex<double> forwardAmplitude(const MieCoefficients& c);
std::complex<double> backwardAmplitudeS1(const MieCoefficients& c);

} // namespace aurorawall::components::glory::mie
