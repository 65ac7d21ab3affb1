#include "physics/spectra.h"

#include "physics/constants.h"

#include <cmath>

namespace aurorawall::physics {

double planckRadiance(double wavelengthNm, double temperatureK)
{
    constexpr double h = kPlanck, c = kSpeedOfLight, k = kBoltzmann; // SI 2019, exact
    const double lambda = wavelengthNm * 1e-9;
    return 2.0 * h * c * c / std::pow(lambda, 5) / std::expm1(h * c / (lambda * k * temperatureK));
}

} // namespace aurorawall::physics
