#include "components/glory/mie/mie_scattering.h"

#include <cmath>

namespace aurorawall::components::glory::mie {

Efficiencies efficiencies(const MieCoefficients& c)
{
    const int terms = int(c.a.size());
    double extinction = 0.0, scattering = 0.0, asymmetrySum = 0.0;
    for (int n = 1; n <= terms; ++n) {
        const std::complex<double> a = c.a[n - 1], b = c.b[n - 1];
        const double weight = 2.0 * n + 1.0;
        extinction += weight * (a.real() + b.real());
        scattering += weight * (std::norm(a) + std::norm(b));
        asymmetrySum += weight / (double(n) * (n + 1.0)) * (a * std::conj(b)).real();
        if (n < terms) {
            const std::complex<double> aNext = c.a[n], bNext = c.b[n];
            asymmetrySum += double(n) * (n + 2.0) / (n + 1.0) * (a * std::conj(aNext) + b * std::conj(bNext)).real();
        }
    }
    const double x2 = c.x * c.x;
    Efficiencies q;
    q.extinction = 2.0 / x2 * extinction;
    q.scattering = 2.0 / x2 * scattering;
    q.asymmetry = scattering > 0.0 ? 2.0 * asymmetrySum / scattering : 0.0;
    q.backscatter = 4.0 * std::norm(backwardAmplitudeS1(c)) / x2;
    return q;
}

Amplitudes amplitudesAtCosine(const MieCoefficients& c, double mu)
{
    Amplitudes s{};
    double piPrevious = 0.0, pi = 1.0; // π₀, π₁
    const int terms = int(c.a.size());
    for (int n = 1; n <= terms; ++n) {
        if (n > 1) {
            const double piNext = (2.0 * n - 1.0) / (n - 1.0) * mu * pi - double(n) / (n - 1.0) * piPrevious;
            piPrevious = pi;
            pi = piNext;
        }
        const double tau = n * mu * pi - (n + 1.0) * piPrevious;
        const double weight = (2.0 * n + 1.0) / (double(n) * (n + 1.0));
        const std::complex<double> a = c.a[n - 1], b = c.b[n - 1];
        s.s1 += weight * (a * pi + b * tau);
        s.s2 += weight * (a * tau + b * pi);
    }
    return s;
}

std::vector<Amplitudes> amplitudes(const MieCoefficients& c, const std::vector<double>& anglesRad)
{
    std::vector<Amplitudes> result;
    result.reserve(anglesRad.size());
    for (double theta : anglesRad) result.push_back(amplitudesAtCosine(c, std::cos(theta)));
    return result;
}

std::complex<double> forwardAmplitude(const MieCoefficients& c)
{
    std::complex<double> sum = 0.0;
    for (size_t i = 0; i < c.a.size(); ++i) sum += (2.0 * (i + 1) + 1.0) * (c.a[i] + c.b[i]);
    return 0.5 * sum;
}

std::complex<double> backwardAmplitudeS1(const MieCoefficients& c)
{
    std::complex<double> sum = 0.0;
    for (size_t i = 0; i < c.a.size(); ++i) {
        const double sign = (i % 2 == 0) ? 1.0 : -1.0; // (−1)ⁿ⁺¹ with n = i + 1
        sum += sign * (2.0 * (i + 1) + 1.0) * (c.a[i] - c.b[i]);
    }
    return 0.5 * sum;
}

} // namespace aurorawall::components::glory::mie
