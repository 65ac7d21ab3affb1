#pragma once
// Mathematical constants of the C++ code, defined once (GLSL has its own in shaders/).
namespace aurorawall {

inline constexpr double kPi = 3.14159265358979323846264338327950288;
inline constexpr double kDegree = kPi / 180.0; // radians per degree

} // namespace aurorawall
