#include "components/glory/mie/mie_coefficients.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace aurorawall::components::glory::mie {

int wiscombeTermCount(double x)
{
    const double cubeRoot = std::cbrt(x);
    double terms = 0.0;
    if (x <= 8.0)
        terms = x + 4.0 * cubeRoot + 1.0;
    else if (x < 4200.0)
        terms = x + 4.05 * cubeRoot + 2.0;
    else
        terms = x + 4.0 * cubeRoot + 2.0;
    return std::max(1, int(terms));
}

MieCoefficients mieCoefficients(double x, RefractiveIndex index, const SeriesSettings& settings)
{
    if (!(x > 0.0) || !std::isfinite(x) || !(index.n >= 1.0) || !(index.k >= 0.0) || !std::isfinite(index.n) ||
        !std::isfinite(index.k))
        throw std::invalid_argument("mieCoefficients: needs x > 0, n >= 1, k >= 0, all finite");
    using C = std::complex<double>;
    const C m = index.m();
    const int terms = settings.terms > 0 ? settings.terms : wiscombeTermCount(x);
    const int startIndex = std::max(terms, int(std::ceil(std::abs(m * x)))) + settings.startAbove;
    const std::vector<C> d = logDerivatives(m * x, terms, startIndex, settings.start);

    MieCoefficients result;
    result.x = x;
    result.a.resize(terms);
    result.b.resize(terms);
    double psiPrevious = std::cos(x), psi = std::sin(x);
    double chiPrevious = -std::sin(x), chi = std::cos(x);
    for (int n = 1; n <= terms; ++n) {
        const double psiNext = (2.0 * n - 1.0) / x * psi - psiPrevious;
        const double chiNext = (2.0 * n - 1.0) / x * chi - chiPrevious;
        psiPrevious = psi;
        psi = psiNext;
        chiPrevious = chi;
        chi = chiNext;
        const C zeta(psi, chi), zetaPrevious(psiPrevious, chiPrevious);
        const C ta = d[n] / m + double(n) / x;
        const C tb = m * d[n] + double(n) / x;
        result.a[n - 1] = (ta * psi - psiPrevious) / (ta * zeta - zetaPrevious);
        result.b[n - 1] = (tb * psi - psiPrevious) / (tb * zeta - zetaPrevious);
    }
    return result;
}

} // namespace aurorawall::components::glory::mie
