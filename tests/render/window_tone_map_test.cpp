// A window's pixels, read back from its framebuffer, against the CPU tone map of wall.png
// (io::toneMapPixel): the window shader and the PNG writer share shaders/render/tone_map.glsl, so
// they differ only by float against double and the 8-bit rounding of the window. ctest runs this
// under xvfb-run (GLFW on Mesa llvmpipe).
#include "gl/context.h"
#include "gl/float_target.h"
#include "gl/full_screen_triangle.h"
#include "gl/functions.h"
#include "io/half_pixels.h"
#include "io/tone_map.h"
#include "render/window_presenter.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdint>
#include <cstdlib>
#include <limits>

using namespace aurorawall;

namespace {

constexpr int kWidth = 64, kHeight = 32;

// Radiance spanning the curves: black, the sRGB toe, mid-tones, highlights far above 1, a
// negative (out of gamut) component, NaN and a value above the half-float range (infinite as a half).
glm::vec3 radianceAt(int x, int y)
{
    const float t = (x + 0.5f) / kWidth, s = (y + 0.5f) / kHeight;
    if (x == 0 && y == 0)
        return glm::vec3(std::numeric_limits<float>::quiet_NaN(), 1e6f, -1.0f);
    return glm::vec3(std::pow(10.0f, -4.0f + 6.0f * t), std::pow(10.0f, -3.0f + 4.0f * s), 0.3f * t * s - 0.05f);
}

// IEEE binary16 bits to their value (the texture holds the radiance as half floats, exactly).
float fromHalf(std::uint16_t h)
{
    const int exponent = (h >> 10) & 31, mantissa = h & 1023;
    const float sign = (h & 0x8000) ? -1.0f : 1.0f;
    if (exponent == 31)
        return mantissa ? std::numeric_limits<float>::quiet_NaN() : sign * std::numeric_limits<float>::infinity();
    if (exponent == 0)
        return sign * std::ldexp(float(mantissa), -24);
    return sign * std::ldexp(float(1024 + mantissa), exponent - 25);
}

} // namespace

TEST(WindowToneMap, WindowPixelsAreTheCpuToneMap)
{
    if (!std::getenv("DISPLAY"))
        GTEST_SKIP() << "no DISPLAY; ctest runs this test under xvfb-run";
    auto context = gl::createContext(gl::Backend::Glfw, {{"tone map", kWidth, kHeight}});
    context->makeCurrent(0);
    gl::FloatTarget tile(kWidth, kHeight);
    // GL rows bottom-up: row y of the texture is window row y.
    std::vector<std::uint16_t> halves(3 * kWidth * kHeight);
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x)
            for (int c = 0; c < 3; ++c)
                halves[3 * (size_t(y) * kWidth + x) + c] = io::halfBits(radianceAt(x, y)[c]);
    tile.uploadRgbHalf(0, kHeight, halves);
    auto radianceInTile = [&](int x, int y) {
        const std::uint16_t* h = &halves[3 * (size_t(y) * kWidth + x)];
        return glm::dvec3(fromHalf(h[0]), fromHalf(h[1]), fromHalf(h[2]));
    };
    const gl::FullScreenTriangle triangle;
    for (io::ToneMap::Curve curve : {io::ToneMap::Curve::AcesFilmic, io::ToneMap::Curve::MagnitudeGamma}) {
        io::ToneMap toneMap;
        toneMap.curve = curve;
        toneMap.exposure = 3.0;
        render::WindowPresenter presenter(std::string(AURORAWALL_SOURCE_DIR) + "/shaders", toneMap);
        presenter.present(*context, 0, tile.texture(), triangle);
        std::vector<std::uint8_t> pixels(4 * kWidth * kHeight);
        gl::glReadBuffer(GL_BACK);
        gl::glPixelStorei(GL_PACK_ALIGNMENT, 1);
        gl::glReadPixels(0, 0, kWidth, kHeight, GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());
        ASSERT_EQ(gl::glGetError(), GLenum(GL_NO_ERROR));
        int worst = 0;
        for (int y = 0; y < kHeight; ++y)
            for (int x = 0; x < kWidth; ++x) {
                const glm::dvec3 cpu = io::toneMapPixel(radianceInTile(x, y), toneMap) * 255.0;
                for (int c = 0; c < 3; ++c) {
                    const int window = pixels[4 * (size_t(y) * kWidth + x) + c];
                    worst = std::max(worst, std::abs(window - int(std::lround(cpu[c]))));
                }
            }
        std::printf("curve %d: largest difference %d of 255 over %d pixels\n", io::toneCurveCode(curve), worst,
                    kWidth * kHeight);
        // One 8-bit step: the window rounds a float, the CPU a double, near a rounding boundary.
        EXPECT_LE(worst, 1) << "curve " << io::toneCurveCode(curve);
        context->swapBuffers(0);
    }
}
