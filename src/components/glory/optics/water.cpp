#include "components/glory/optics/water.h"

#include <cmath>

namespace aurorawall::components::glory::optics {

double waterRefractiveIndex(double wavelengthNm)
{
    constexpr double kA[4] = {5.684027565e-1, 1.726177391e-1, 2.086189578e-2, 1.130748688e-1};
    constexpr double kB[4] = {5.101829712e-3, 1.821153936e-2, 2.620722293e-2, 1.069792721e1}; // µm²
    const double l2 = (wavelengthNm * 1e-3) * (wavelengthNm * 1e-3);
    double n2 = 1.0;
    for (int i = 0; i < 4; ++i)
        n2 += kA[i] * l2 / (l2 - kB[i]);
    return std::sqrt(n2);
}

} // namespace aurorawall::components::glory::optics
