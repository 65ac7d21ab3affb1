#include "components/plasma/simulation/dispersion.h"

#include "physics/constants.h"

#include <cmath>
#include <stdexcept>

namespace aurorawall::components::plasma::simulation {

double leapfrogPlasmaFrequency(double wpDt)
{
    if (!(wpDt > 0.0 && wpDt < 2.0))
        throw std::domain_error("leapfrogPlasmaFrequency: the leapfrog needs 0 < omega_p dt < 2");
    return 2.0 * std::asin(0.5 * wpDt) / wpDt;
}

double borisRotationPerStep(double wcDt)
{
    return 2.0 * std::atan(0.5 * wcDt);
}

double twoStreamGrowthRate(double kv0)
{
    const double omegaSquared = kv0 * kv0 + 0.5 - std::sqrt(0.5) * std::sqrt(0.5 + 4.0 * kv0 * kv0);
    return omegaSquared < 0.0 ? std::sqrt(-omegaSquared) : 0.0;
}

std::complex<double> plasmaDispersionZ(std::complex<double> zeta)
{
    using complex = std::complex<double>;
    const complex i(0.0, 1.0);
    const double sqrtPi = std::sqrt(physics::kPi);
    if (std::abs(zeta) < 4.0) {
        // F(ζ) = ζ Σ_n (−2ζ²)^n/(2n + 1)!!
        complex term = zeta, dawson = zeta;
        for (int n = 1; n < 200 && std::abs(term) > 1e-18 * std::abs(dawson); ++n) {
            term *= -2.0 * zeta * zeta / double(2 * n + 1);
            dawson += term;
        }
        return i * sqrtPi * std::exp(-zeta * zeta) - 2.0 * dawson;
    }
    if (zeta.imag() < 0.0)
        return 2.0 * i * sqrtPi * std::exp(-zeta * zeta) - plasmaDispersionZ(-zeta);
    // w(ζ) = (i/√π) / (ζ − (1/2)/(ζ − 1/(ζ − (3/2)/(ζ − ...)))) and Z = i√π w = −1/(ζ − ...).
    complex tail = zeta;
    for (int k = 400; k >= 1; --k)
        tail = zeta - 0.5 * k / tail;
    return -1.0 / tail;
}

std::complex<double> landauRoot(double kDebyeLength)
{
    if (!(kDebyeLength > 0.0))
        throw std::domain_error("landauRoot: k lambda_D must be > 0");
    using complex = std::complex<double>;
    const double k2 = kDebyeLength * kDebyeLength;
    const double scale = std::sqrt(2.0) * kDebyeLength; // ζ = (ω/ω_p)/scale
    complex zeta = std::sqrt(1.0 + 3.0 * k2) / scale - complex(0.0, 0.1);
    for (int iteration = 0; iteration < 100; ++iteration) {
        const complex z = plasmaDispersionZ(zeta);
        const complex dz = -2.0 * (1.0 + zeta * z);
        const complex d = 1.0 + (1.0 + zeta * z) / k2;
        const complex dd = (z + zeta * dz) / k2;
        const complex step = d / dd;
        zeta -= step;
        if (std::abs(step) < 1e-15 * std::abs(zeta))
            break;
    }
    return zeta * scale;
}

double diocotronGrowthRate(double ka, double kL)
{
    if (!(ka > 0.0) || !(2.0 * ka < kL) || !std::isfinite(kL))
        throw std::domain_error("diocotron: needs k > 0 and a strip thinner than the box");
    // g(0) and g(2a) with the exponentials of −kL only, finite for any width.
    const double images = 1.0 - std::exp(-kL);
    const double g0 = (2.0 - images) / images;
    const double g2a = (std::exp(2.0 * ka - kL) + std::exp(-2.0 * ka)) / images;
    const double fill = 2.0 * ka / kL;
    const double shift = g0 - 2.0 * ka * (1.0 - fill);
    const double square = g2a * g2a - shift * shift;
    return square > 0.0 ? 0.5 * std::sqrt(square) : 0.0;
}

} // namespace aurorawall::components::plasma::simulation
