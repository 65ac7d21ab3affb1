#pragma once
// Random curtains for the footprint map's tests (CPU and GPU builds): polylines sampled from random
// control points in the 30° cap around the north pole.
#include "components/aurora/physics/curtain_geometry.h"
#include "physics/constants.h"

#include <glm/glm.hpp>

#include <cmath>
#include <random>
#include <vector>

namespace aurorawall::components::aurora::physics::random_curtains {

inline constexpr double kR = 6371.0;

inline double angle(const glm::dvec3& a, const glm::dvec3& b)
{
    return 2.0 * std::atan2(glm::length(a - b), glm::length(a + b));
}

// A direction uniformly distributed on the cap within maxAngle of `centre`.
inline glm::dvec3 randomInCap(std::mt19937_64& rng, const glm::dvec3& centre, const glm::dvec3& east, double maxAngle)
{
    std::uniform_real_distribution<double> uniform(0.0, 1.0);
    const double theta = std::acos(1.0 - uniform(rng) * (1.0 - std::cos(maxAngle)));
    const double azimuth = 2.0 * aurorawall::physics::kPi * uniform(rng);
    const glm::dvec3 north = glm::cross(centre, east);
    return std::cos(theta) * centre + std::sin(theta) * (std::cos(azimuth) * east + std::sin(azimuth) * north);
}

// `count` random curtains of about lengthKm: 10 spans with random turns of up to ±34°, starting in the
// 30° cap around the north pole.
inline std::vector<CurtainPolyline> randomCurtains(std::mt19937_64& rng, int count, double lengthKm, double spacingKm)
{
    std::uniform_real_distribution<double> uniform(0.0, 1.0);
    const glm::dvec3 pole(0, 0, 1), east(0, -1, 0);
    std::vector<CurtainPolyline> out;
    for (int c = 0; c < count; ++c) {
        glm::dvec3 p = randomInCap(rng, pole, east, 30.0 * aurorawall::physics::kPi / 180.0);
        glm::dvec3 tangent = glm::normalize(glm::cross(p, randomInCap(rng, pole, east, aurorawall::physics::kPi)));
        const double step = lengthKm / 10.0 / kR;
        std::vector<glm::dvec2> control;
        for (int k = 0; k <= 10; ++k) {
            control.push_back(latLonFromUnit(p));
            const double turn = (uniform(rng) - 0.5) * 1.2;
            tangent = std::cos(turn) * tangent + std::sin(turn) * glm::cross(p, tangent);
            const glm::dvec3 next = std::cos(step) * p + std::sin(step) * tangent;
            tangent = glm::normalize(std::cos(step) * tangent - std::sin(step) * p);
            p = glm::normalize(next);
        }
        out.push_back(sampleCurtain(control, kR, spacingKm));
    }
    return out;
}

} // namespace aurorawall::components::aurora::physics::random_curtains
