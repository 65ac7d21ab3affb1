// The default airmass method as the GPU runs it: the shared GLSL text compiled by the
// GL driver (llvmpipe in CI) returns a finite value for finite inputs of any magnitude, as the C++
// float and double evaluations of the same text do (tests/physics/atmosphere/airmass_tests.cpp).
#include "physics/atmosphere/accuracy_report.h"
#include "physics/atmosphere/airmass.h"
#include "physics/atmosphere/airmass_accuracy.h"
#include "gl/context.h"
#include "random_rays.h"

#include <gtest/gtest.h>

#include <cmath>

namespace aurorawall::physics::atmosphere {
namespace {

TEST(AirmassInShader, DefaultIsFiniteForAnyFiniteInput)
{
    auto context = gl::createContext(gl::Backend::Egl);
    const std::vector<AirmassRay> rays = randomFiniteRays(20000, 7, -37.0, 37.0); // float's range
    const std::vector<double> values =
        evaluateAirmassInShader(findAirmassMethod(kDefaultAirmassMethod)->glslFunction, rays);
    ASSERT_EQ(values.size(), rays.size());
    int nonFinite = 0;
    for (size_t i = 0; i < rays.size(); ++i) {
        if (!std::isfinite(values[i])) ++nonFinite;
        EXPECT_TRUE(std::isfinite(evaluateAirmass(*findAirmassMethod(kDefaultAirmassMethod), rays[i], AirmassPrecision::Float32)));
    }
    EXPECT_EQ(nonFinite, 0);
}

// The same text on the GPU and in C++ float agree on ordinary rays (the sweep's agreement, 1.7e-5,
// is in docs/ACCURACY.md); here a spot check that the shader is the default and not a stand-in.
TEST(AirmassInShader, DefaultMatchesCpuFloatOnTheSweep)
{
    auto context = gl::createContext(gl::Backend::Egl);
    const std::vector<AirmassRay> rays = airmassAccuracyRays();
    const AirmassMethod& method = *findAirmassMethod(kDefaultAirmassMethod);
    const std::vector<double> values = evaluateAirmassInShader(method.glslFunction, rays);
    double worst = 0.0;
    for (size_t i = 0; i < rays.size(); ++i) {
        const double cpu = evaluateAirmass(method, rays[i], AirmassPrecision::Float32);
        worst = std::max(worst, std::abs(values[i] - cpu) / std::max(std::abs(cpu), 1e-30));
    }
    EXPECT_LE(worst, 1e-4);
}

} // namespace
} // namespace aurorawall::physics::atmosphere
