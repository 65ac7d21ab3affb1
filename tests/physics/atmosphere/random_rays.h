#pragma once
// Rays for the "any finite input" tests of the default airmass method.
#include "physics/atmosphere/airmass.h"

#include <cmath>
#include <random>
#include <vector>

namespace aurorawall::physics::atmosphere {

// Every length and direction component a random finite number from 10^minExponent to 10^maxExponent
// in magnitude, either sign, 5% exact zeros; H > 0 and R ≥ 0, as the airmass command requires.
inline std::vector<AirmassRay> randomFiniteRays(int count, unsigned seed, double minExponent, double maxExponent)
{
    std::mt19937_64 random(seed);
    std::uniform_real_distribution<double> exponent(minExponent, maxExponent), unit(0.0, 1.0);
    auto value = [&]() {
        if (unit(random) < 0.05) return 0.0;
        const double magnitude = std::pow(10.0, exponent(random));
        return unit(random) < 0.5 ? -magnitude : magnitude;
    };
    const double smallest = std::pow(10.0, minExponent);
    std::vector<AirmassRay> rays;
    for (int i = 0; i < count; ++i) {
        AirmassRay ray;
        ray.origin = {value(), value(), value()};
        ray.direction = {value(), value(), value()};
        ray.t0 = value();
        ray.t1 = value();
        ray.scaleHeight = std::abs(value()) + smallest;
        ray.planetRadius = std::abs(value());
        rays.push_back(ray);
    }
    return rays;
}

} // namespace aurorawall::physics::atmosphere
