#include "components/fluid_detail/simulation/periodic_field.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace aurorawall::components::fluid_detail::simulation {

bool isPowerOfTwo(int n)
{
    return n > 0 && (n & (n - 1)) == 0;
}

PeriodicField::PeriodicField(int nx_, int ny_, double hx_, double hy_)
    : nx(nx_), ny(ny_), hx(hx_), hy(hy_)
{
    if (!isPowerOfTwo(nx) || !isPowerOfTwo(ny))
        throw std::invalid_argument("periodic grid " + std::to_string(nx) + "x" + std::to_string(ny) +
                                    ": sizes must be powers of two");
    values.assign(std::size_t(nx) * std::size_t(ny), 0.0);
}

double PeriodicField::mean() const
{
    double sum = 0.0;
    for (double q : values)
        sum += q;
    return sum / double(values.size());
}

double PeriodicField::rms() const
{
    double sum = 0.0;
    for (double q : values)
        sum += q * q;
    return std::sqrt(sum / double(values.size()));
}

void PeriodicField::subtractMean()
{
    const double m = mean();
    for (double& q : values)
        q -= m;
}

} // namespace aurorawall::components::fluid_detail::simulation
