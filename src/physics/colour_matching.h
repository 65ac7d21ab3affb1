#pragma once
// The CIE 1931 2° standard observer: the colour matching functions x̄, ȳ, z̄ (CIE 15:2004, table T.4),
// tabulated every 5 nm from 380 to 780 nm.
#include <glm/glm.hpp>

namespace aurorawall::physics {

constexpr double kCieFirstNm = 380.0;
constexpr double kCieLastNm = 780.0;
constexpr double kCieStepNm = 5.0;

// (x̄, ȳ, z̄) at λ (nm), linear between the 5 nm rows; zero outside [380, 780] nm.
glm::dvec3 colourMatching(double wavelengthNm);

} // namespace aurorawall::physics
