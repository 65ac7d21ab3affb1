#pragma once
// Lets one shader module compile as GLSL and as C++, so the CPU reference and the shader
// share one text (the approach of Bruneton's precomputed atmospheric scattering).
//
// A shared module (shaders/**/*.glsl without a #version line) may use:
//   - the scalar type `real` and the vectors `vec2 vec3 vec4` built from it,
//     literals written as real(0.5) so they take the module's precision;
//   - the GLSL built-ins listed below; functions that take and return values (no in/out/inout).
// The shader assembler prepends `#define real float`. C++ includes the module inside a
// namespace that fixes the precision, f32 or f64 under the including folder's namespace (an
// unnamed one inside where another file of the folder compiles the same module):
//
//   namespace aurorawall::physics::atmosphere::f64 {
//   AURORAWALL_GLSL_PRECISION(double)
//   #include "physics/atmosphere/airmass.glsl"
//   }
#include <cmath>
#include <cstdint>
#include <cstring>
#include <glm/glm.hpp>

#define AURORAWALL_GLSL_PRECISION(T)                                                         \
    using real = T;                                                                          \
    using vec2 = glm::vec<2, T, glm::defaultp>;                                              \
    using vec3 = glm::vec<3, T, glm::defaultp>;                                              \
    using vec4 = glm::vec<4, T, glm::defaultp>;                                              \
    using glm::abs; using glm::clamp; using glm::cross; using glm::dot; using glm::length;  \
    using glm::max; using glm::min; using glm::mix; using glm::normalize; using glm::sign;  \
    using glm::inversesqrt; using glm::smoothstep; using glm::step; using glm::fract;       \
    using glm::floor; using std::exp; using std::log; using std::sqrt; using std::pow;      \
    using std::sin; using std::cos; using std::tan; using std::atan; using std::acos;      \
    using std::asin; using std::exp2; using std::log2;                                       \
    /* GLSL's two-argument atan is atan2. */                                                 \
    [[maybe_unused]] inline real atan(real y, real x) { return std::atan2(y, x); }
