#pragma once
// The planet frame of every scene: centre at the origin, z toward the north pole, x toward
// longitude 180 deg and y toward 90 deg W (the frame of the paper's published benchmark camera).
#include "physics/constants.h"

#include <glm/glm.hpp>

#include <cmath>

namespace aurorawall::common {

// Unit vector of geographic latitude/longitude in degrees: (-cos lat cos lon, -cos lat sin lon, sin lat).
inline glm::dvec3 unitFromLatLon(double latitudeDeg, double longitudeDeg)
{
    const double lat = latitudeDeg * physics::kDegree, lon = longitudeDeg * physics::kDegree;
    return {-std::cos(lat) * std::cos(lon), -std::cos(lat) * std::sin(lon), std::sin(lat)};
}

} // namespace aurorawall::common
