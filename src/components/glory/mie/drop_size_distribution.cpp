#include "components/glory/mie/drop_size_distribution.h"

#include <boost/math/distributions/gamma.hpp>

#include <cmath>
#include <stdexcept>

namespace aurorawall::components::glory::mie {

DropSizeDistribution DropSizeDistribution::singleSize(double radiusUm)
{
    if (!(radiusUm > 0.0) || !std::isfinite(radiusUm)) throw std::invalid_argument("drop radius must be > 0");
    return {radiusUm, 0.0};
}

DropSizeDistribution DropSizeDistribution::gamma(double effectiveRadiusUm, double effectiveVariance)
{
    if (!(effectiveRadiusUm > 0.0) || !std::isfinite(effectiveRadiusUm))
        throw std::invalid_argument("effective radius must be > 0");
    if (!(effectiveVariance > 0.0 && effectiveVariance < 0.5))
        throw std::invalid_argument("effective variance must be in (0, 0.5)");
    return {effectiveRadiusUm, effectiveVariance};
}

double DropSizeDistribution::logDensity(double radiusUm) const
{
    const double mode = shape() * scaleUm();
    if (mode <= 0.0) return shape() * std::log(radiusUm) - radiusUm / scaleUm();
    // α ln(r/r_mode) − (r − r_mode)/b, with r_mode = α b: free of overflow for a large α.
    return shape() * std::log(radiusUm / mode) - (radiusUm - mode) / scaleUm();
}

std::pair<double, double> DropSizeDistribution::radiusRangeUm() const
{
    if (isSingleSize()) return {radius_, radius_};
    constexpr double kTail = 1e-12;
    // r^j n(r) ∝ r^(α+j) e^(−r/b): a gamma distribution of shape α + j + 1 and scale b.
    const boost::math::gamma_distribution<double> areaWeighted(shape() + 3.0, scaleUm());
    const boost::math::gamma_distribution<double> forwardWeighted(shape() + 5.0, scaleUm());
    return {boost::math::quantile(areaWeighted, kTail),
            boost::math::quantile(boost::math::complement(forwardWeighted, kTail))};
}

} // namespace aurorawall::components::glory::mie
