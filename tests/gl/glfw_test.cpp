// Two GLFW windows (ctest runs this under xvfb-run) render the pattern exactly as EGL does.
#include "test_pattern.h"

#include "gl/context.h"
#include "gl/functions.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <cstring>

namespace aurorawall::gl::test {
namespace {

TEST(Glfw, TwoWindowsMatchEgl)
{
    if (!std::getenv("DISPLAY"))
        GTEST_SKIP() << "no DISPLAY; ctest runs this test under xvfb-run";
    std::vector<float> egl;
    {
        auto context = createContext(Backend::Egl);
        egl = renderPattern();
    }
    auto context = createContext(Backend::Glfw, {{"left", 2 * kWidth, 2 * kHeight, 0, 0},
                                                 {"right", 2 * kWidth, 2 * kHeight, 2 * kWidth, 0}});
    ASSERT_EQ(context->windowCount(), 2);
    for (int i = 0; i < context->windowCount(); ++i) {
        context->makeCurrent(i);
        FloatTarget target(kWidth, kHeight); // framebuffers belong to one window's context
        drawPattern(target);
        const std::vector<float> pixels = target.readback();
        ASSERT_EQ(pixels.size(), egl.size());
        EXPECT_EQ(std::memcmp(pixels.data(), egl.data(), egl.size() * sizeof(float)), 0) << "window " << i;

        context->bindWindowFramebuffer(i);
        target.blitTo(0, 2 * kWidth, 2 * kHeight);
        context->swapBuffers(i);
        EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR)) << "window " << i;
    }
    context->pollEvents();
    EXPECT_FALSE(context->closeRequested());
}

// GLFW contexts one after another: glfwTerminate closes libGL, the next one loads it and the functions again.
TEST(Glfw, SecondContextAfterTerminate)
{
    if (!std::getenv("DISPLAY"))
        GTEST_SKIP() << "no DISPLAY; ctest runs this test under xvfb-run";
    for (int round = 0; round < 2; ++round) {
        auto context = createContext(Backend::Glfw, {{"again", kWidth, kHeight}});
        EXPECT_NE(context->rendererName(), "") << "round " << round;
        EXPECT_LE(worstErrorOverBound(renderPattern(), referencePattern()), 1.0) << "round " << round;
    }
}

} // namespace
} // namespace aurorawall::gl::test
