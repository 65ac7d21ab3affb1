// EGL and OSMesa render the test pattern like the CPU double reference, and identically.
#include "test_pattern.h"

#include "gl/context.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <cstring>

namespace aurorawall::gl::test {
namespace {

std::vector<double> flippedRows(const std::vector<double>& pixels)
{
    std::vector<double> flipped;
    for (int y = kHeight - 1; y >= 0; --y)
        flipped.insert(flipped.end(), pixels.begin() + 4 * y * kWidth, pixels.begin() + 4 * (y + 1) * kWidth);
    return flipped;
}

void expectMatchesReference(Backend backend)
{
    auto context = createContext(backend);
    EXPECT_NE(context->rendererName(), "");
    const std::vector<float> gpu = renderPattern();
    const std::vector<double> cpu = referencePattern();
    const double worst = worstErrorOverBound(gpu, cpu);
    std::printf("%s: the largest error is %.3g of GLSL's bound\n", context->rendererName().c_str(), worst);
    EXPECT_LE(worst, 1.0) << context->rendererName();
    // Rows are bottom-up (documented in float_target.h): the top-down order must not match.
    EXPECT_GT(worstErrorOverBound(gpu, flippedRows(cpu)), 1.0);
}

TEST(Egl, RendersPatternLikeCpuDouble) { expectMatchesReference(Backend::Egl); }

TEST(Osmesa, RendersPatternLikeCpuDouble) { expectMatchesReference(Backend::Osmesa); }

// OSMesa is always Mesa's llvmpipe; EGL picks a GPU where there is one (egl_context.cpp). Where EGL
// too runs on llvmpipe, the same Mesa through the same libglapi, the two draw bit-identical pixels and
// coexist in one process (contexts used one after the other); a GPU is held to the CPU reference instead
// (RendersPatternLikeCpuDouble).
bool eglRunsOnLlvmpipe()
{
    auto context = createContext(Backend::Egl);
    return context->rendererName().rfind("llvmpipe", 0) == 0;
}

TEST(Headless, EglAndOsmesaAreBitIdentical)
{
    if (!eglRunsOnLlvmpipe())
        GTEST_SKIP() << "EGL runs on a GPU here, OSMesa on llvmpipe: two devices, not bit-identical";
    std::vector<float> egl, osmesa;
    {
        auto context = createContext(Backend::Egl);
        egl = renderPattern();
    }
    {
        auto context = createContext(Backend::Osmesa);
        osmesa = renderPattern();
    }
    ASSERT_EQ(egl.size(), osmesa.size());
    EXPECT_EQ(std::memcmp(egl.data(), osmesa.data(), egl.size() * sizeof(float)), 0);
}

TEST(Headless, TwoLiveContextsTakeTurns)
{
    if (!eglRunsOnLlvmpipe())
        GTEST_SKIP() << "EGL runs on a GPU here, OSMesa on llvmpipe: two devices, not bit-identical";
    auto egl = createContext(Backend::Egl);
    auto osmesa = createContext(Backend::Osmesa);
    const std::vector<float> fromOsmesa = renderPattern();
    egl->makeCurrent();
    const std::vector<float> fromEgl = renderPattern();
    ASSERT_EQ(fromEgl.size(), fromOsmesa.size());
    EXPECT_EQ(std::memcmp(fromEgl.data(), fromOsmesa.data(), fromEgl.size() * sizeof(float)), 0);
}

} // namespace
} // namespace aurorawall::gl::test
