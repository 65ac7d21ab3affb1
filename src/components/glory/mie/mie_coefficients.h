#pragma once
// The Mie coefficients aₙ, bₙ of a homogeneous sphere (Bohren & Huffman 1983, "Absorption and
// Scattering of Light by Small Particles", ch. 4; Wiscombe 1980, "Improved Mie scattering
// algorithms", Appl. Opt. 19, 1505).
//
// Sign convention (Wiscombe's, time dependence e^{+iωt}): the refractive index relative to the
// medium is m = n − ik with k ≥ 0 absorbing. Bohren & Huffman write m = n + ik (e^{−iωt}); their
// aₙ, bₙ, S1, S2 are the complex conjugates of the ones here, and the efficiencies are the same.
#include "components/glory/mie/log_derivative.h"

#include <complex>
#include <vector>

namespace aurorawall::components::glory::mie {

// m = n − ik: n the real part (1 ≤ n ≤ 3 tested), k ≥ 0 the absorption (0 ≤ k ≤ 10 tested).
struct RefractiveIndex {
    double n = 1.0;
    double k = 0.0;
    std::complex<double> m() const { return {n, -k}; }
};

// Wiscombe's number of terms (1980, eq. 25 and Fig. 1), the integer part of
//   x + 4 x^(1/3) + 1      for x ≤ 8,
//   x + 4.05 x^(1/3) + 2   for 8 < x < 4200,
//   x + 4 x^(1/3) + 2      for x ≥ 4200 (tested to 2e4; used as it stands above),
// and at least 1.
int wiscombeTermCount(double x);

// How the series is summed and Dₙ(mx) started; the defaults are the library's choice.
struct SeriesSettings {
    int terms = 0;      // 0: wiscombeTermCount(x)
    int startAbove = 15; // Dₙ(mx) starts at max(terms, |mx|) + startAbove
    RecurrenceStart start = RecurrenceStart::ContinuedFraction;
};

struct MieCoefficients {
    double x = 0.0;                    // size parameter 2πr/λ
    std::vector<std::complex<double>> a; // a[n−1] = aₙ, n = 1 … N
    std::vector<std::complex<double>> b;
};

// aₙ = [(Dₙ(mx)/m + n/x) ψₙ(x) − ψₙ₋₁(x)] / [(Dₙ(mx)/m + n/x) ζₙ(x) − ζₙ₋₁(x)],
// bₙ = [(m Dₙ(mx) + n/x) ψₙ(x) − ψₙ₋₁(x)] / [(m Dₙ(mx) + n/x) ζₙ(x) − ζₙ₋₁(x)]
// (Bohren & Huffman eq. 4.88 in this sign convention), with the Riccati–Bessel functions ψₙ = x jₙ(x),
// χₙ = −x yₙ(x), ζₙ = ψₙ + iχₙ by upward recurrence fₙ₊₁ = (2n+1)/x fₙ − fₙ₋₁ from ψ₋₁ = cos x,
// ψ₀ = sin x, χ₋₁ = −sin x, χ₀ = cos x. x > 0, n ≥ 1, k ≥ 0.
MieCoefficients mieCoefficients(double x, RefractiveIndex index, const SeriesSettings& settings = {});

} // namespace aurorawall::components::glory::mie
