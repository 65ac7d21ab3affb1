#pragma once
// Lets one shader module compile as GLSL and as C++, so the CPU reference and the shader
// share one text (the approach of Bruneton's precomputed atmospheric scattering).
//
// A shared module (shaders/**/*.glsl without a #version line) may use:
//   - the scalar type `real` and the vectors `vec2 vec3 vec4` built from it,
//     literals written as real(0.5) so they take the module's precision;
//   - the GLSL built-ins listed below; functions that take and return values (no in/out/inout);
//   - sampler2D and sampler2DArray through texelFetch and textureLod (level 0): C++ objects that hold the
//     texels the GPU is given, read as GL specifies (below).
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

#include <algorithm>
#include <cassert>
#include <vector>

namespace aurorawall::common {

// An RGBA32F texture's level 0 as uploaded: texels[4 (((layer · height) + y) · width + x) + channel],
// y = 0 the first row uploaded. T is the precision the texels are read in.
template <class T>
struct GlslSampler {
    int width = 0, height = 0, layers = 1;
    std::vector<float> texels;

    glm::vec<4, T, glm::defaultp> at(int x, int y, int layer) const
    {
        assert(x >= 0 && x < width && y >= 0 && y < height && layer >= 0 && layer < layers);
        const float* t = &texels[4 * ((size_t(layer) * height + y) * width + x)];
        return {t[0], t[1], t[2], t[3]};
    }
};

// GL_LINEAR with GL_CLAMP_TO_EDGE along one axis of n texels (GL 4.5 core, section 8.14.2): the texel
// centres sit at (i + 1/2)/n, so u = n s − 1/2 lies between texels i0 = ⌊u⌋ and i0 + 1 (each clamped to
// [0, n − 1]) with weight α = u − ⌊u⌋ on the second. A GPU rounds α to 8 bits of fraction; this does not.
template <class T>
struct GlslLinearAxis {
    int i0, i1;
    T alpha;
};

template <class T>
GlslLinearAxis<T> glslLinearAxis(T s, int n)
{
    const T u = s * T(n) - T(0.5);
    const T below = std::floor(u);
    const int i = static_cast<int>(below);
    return {std::clamp(i, 0, n - 1), std::clamp(i + 1, 0, n - 1), u - below};
}

} // namespace aurorawall::common

#define AURORAWALL_GLSL_PRECISION(T)                                                      \
    using real = T;                                                                       \
    using vec2 = glm::vec<2, T, glm::defaultp>;                                           \
    using vec3 = glm::vec<3, T, glm::defaultp>;                                           \
    using vec4 = glm::vec<4, T, glm::defaultp>;                                           \
    using ivec2 = glm::ivec2;                                                             \
    using sampler2D = aurorawall::common::GlslSampler<T>;                                 \
    using sampler2DArray = aurorawall::common::GlslSampler<T>;                            \
    using glm::abs; using glm::clamp; using glm::cross; using glm::dot; using glm::length; \
    using glm::max; using glm::min; using glm::mix; using glm::normalize; using glm::sign; \
    using glm::inversesqrt; using glm::smoothstep; using glm::step; using glm::fract;     \
    using glm::floor; using std::exp; using std::log; using std::sqrt; using std::pow;    \
    using std::sin; using std::cos; using std::tan; using std::atan; using std::acos;     \
    using std::asin; using std::exp2; using std::log2; using std::ceil; using glm::mod;   \
    /* GLSL's two-argument atan is atan2. */                                              \
    [[maybe_unused]] inline real atan(real y, real x) { return std::atan2(y, x); }        \
    /* texelFetch: the texel itself (GL 4.5 core, section 8.14.2; level 0). */            \
    [[maybe_unused]] inline vec4 texelFetch(const sampler2D& s, ivec2 p, int)             \
    {                                                                                     \
        return s.at(p.x, p.y, 0);                                                         \
    }                                                                                     \
    /* textureLod at level 0 of a linear, clamp-to-edge array: bilinear within the layer */ \
    /* round(r) clamped to the layers (GL 4.5 core, section 8.14.2). */                   \
    [[maybe_unused]] inline vec4 textureLod(const sampler2DArray& s, vec3 c, real)        \
    {                                                                                     \
        const auto x = aurorawall::common::glslLinearAxis(c.x, s.width);                  \
        const auto y = aurorawall::common::glslLinearAxis(c.y, s.height);                 \
        const int layer = std::clamp(int(std::floor(c.z + real(0.5))), 0, s.layers - 1);  \
        return mix(mix(s.at(x.i0, y.i0, layer), s.at(x.i1, y.i0, layer), x.alpha),        \
                   mix(s.at(x.i0, y.i1, layer), s.at(x.i1, y.i1, layer), x.alpha), y.alpha); \
    }
