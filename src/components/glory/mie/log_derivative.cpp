#include "components/glory/mie/log_derivative.h"

#include <cmath>
#include <stdexcept>

namespace aurorawall::components::glory::mie {

std::complex<double> logDerivativeContinuedFraction(std::complex<double> z, int n)
{
    using C = std::complex<double>;
    constexpr double kTiny = 1e-300;
    constexpr double kEpsilon = 1e-16;
    constexpr int kMaxIterations = 10'000'000;
    const double nu = n + 0.5;
    // f = b₀ − 1/(b₁ − 1/(b₂ − …)), b_j = 2(ν + j)/z.
    C f = 2.0 * nu / z;
    if (f == 0.0) f = kTiny;
    C c = f, d = 0.0;
    for (int j = 1; j < kMaxIterations; ++j) {
        const C b = 2.0 * (nu + j) / z;
        d = b - d;
        if (d == 0.0) d = kTiny;
        c = b - 1.0 / c;
        if (c == 0.0) c = kTiny;
        d = 1.0 / d;
        const C delta = c * d;
        f *= delta;
        if (std::abs(delta - 1.0) < kEpsilon) return -double(n) / z + f;
    }
    throw std::runtime_error("Lentz continued fraction for D_n(z) did not converge");
}

std::vector<std::complex<double>> logDerivatives(std::complex<double> z, int nTerms, int startIndex,
                                                 RecurrenceStart start)
{
    if (startIndex < nTerms) throw std::invalid_argument("logDerivatives: startIndex < nTerms");
    std::vector<std::complex<double>> d(nTerms + 1);
    std::complex<double> dn =
        start == RecurrenceStart::ContinuedFraction ? logDerivativeContinuedFraction(z, startIndex) : 0.0;
    for (int n = startIndex; n > 0; --n) {
        if (n <= nTerms) d[n] = dn;
        const std::complex<double> nOverZ = double(n) / z;
        dn = nOverZ - 1.0 / (dn + nOverZ);
    }
    d[0] = dn;
    return d;
}

} // namespace aurorawall::components::glory::mie
