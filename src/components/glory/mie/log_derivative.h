#pragma once
// The logarithmic derivative Dₙ(z) = ψₙ'(z)/ψₙ(z) of the Riccati–Bessel function ψₙ(z) = z jₙ(z)
// at a complex argument z = m·x, by downward recurrence (Bohren & Huffman 1983, eq. 4.89; Wiscombe
// 1980, Appl. Opt. 19, 1505, eq. 9), which is stable for every z.
#include <complex>
#include <vector>

namespace aurorawall::components::glory::mie {

// How the downward recurrence gets its first value, at index `startIndex`.
enum class RecurrenceStart {
    // Dₙ(z) itself, from Lentz's continued fraction (Lentz 1976, Appl. Opt. 15, 668): exact to rounding.
    ContinuedFraction,
    // Dₙ = 0: only correct once the recurrence has run far enough down to forget it.
    Zero,
};

// Dₙ(z) at the start index from Lentz's continued fraction: Dₙ(z) = −n/z + J_{n−½}(z)/J_{n+½}(z),
// the Bessel ratio J_{ν−1}/J_ν = 2ν/z − 1/(2(ν+1)/z − 1/(2(ν+2)/z − …)), evaluated by the modified
// Lentz method (Thompson & Barnett 1986, J. Comput. Phys. 64, 490) to relative 1e-16.
std::complex<double> logDerivativeContinuedFraction(std::complex<double> z, int n);

// D₀(z) … D_{nTerms}(z): started at startIndex ≥ nTerms, then D_{n−1} = n/z − 1/(Dₙ + n/z).
std::vector<std::complex<double>> logDerivatives(std::complex<double> z, int nTerms, int startIndex,
                                                 RecurrenceStart start);

} // namespace aurorawall::components::glory::mie
