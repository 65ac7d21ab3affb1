// The float target's two attachments and its row regions: a band of half floats uploaded into some
// rows reads back exactly and leaves the other rows alone; the work attachment reads back what the
// shader wrote to location 1.
#include "gl/context.h"
#include "gl/float_target.h"
#include "gl/full_screen_triangle.h"
#include "gl/functions.h"
#include "gl/shader_program.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>

namespace aurorawall::gl {
namespace {

// IEEE binary16 -> float, by the definition: sign, 5 exponent bits (bias 15), 10 fraction bits.
float halfToFloat(std::uint16_t h)
{
    const int sign = h >> 15, exponent = (h >> 10) & 0x1f, fraction = h & 0x3ff;
    const float magnitude = exponent == 0 ? std::ldexp(float(fraction), -24)
                                          : std::ldexp(float(1024 + fraction), exponent - 25);
    return sign ? -magnitude : magnitude;
}

// A 7-pixel-wide target (rows of 42 bytes of halves: not a multiple of 4) drawn with radiance
// (x, y, x + y, 1) and work 100 y + x.
class FloatTargetRows : public ::testing::Test {
protected:
    static constexpr int kWidth = 7, kHeight = 10;

    void SetUp() override
    {
        context_ = createContext(Backend::Egl);
        target_ = std::make_unique<FloatTarget>(kWidth, kHeight);
        Program program = Program::graphics(fullScreenTriangleVertexShader(), {{}, {{"two_outputs.glsl", R"(
layout(location = 0) out vec4 radiance;
layout(location = 1) out float work;
void main()
{
    vec2 p = floor(gl_FragCoord.xy);
    radiance = vec4(p.x, p.y, p.x + p.y, 1.0);
    work = 100.0 * p.y + p.x;
})"}}});
        FullScreenTriangle triangle;
        target_->bind();
        program.use();
        triangle.draw();
    }

    std::unique_ptr<Context> context_;
    std::unique_ptr<FloatTarget> target_;
};

TEST_F(FloatTargetRows, WorkAttachmentHoldsLocationOne)
{
    const int firstRow = 2, rows = 5;
    const std::vector<float> work = target_->readbackWork(firstRow, rows);
    ASSERT_EQ(work.size(), size_t(kWidth * rows));
    for (int j = 0; j < rows; ++j)
        for (int x = 0; x < kWidth; ++x)
            EXPECT_EQ(work[size_t(j * kWidth + x)], 100.0f * float(firstRow + j) + float(x)) << x << "," << j;
    // Reading the work leaves the radiance the one read.
    EXPECT_EQ(target_->readbackRgb(0, 1)[3], 1.0f); // pixel (1, 0): red = x
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(FloatTargetRows, BandUploadedIntoRowsReadsBackExactly)
{
    const int firstRow = 3, rows = 4;
    // Halves across the range: subnormals, both signs, up to the largest finite (no NaN or infinity).
    std::vector<std::uint16_t> band(size_t(3 * kWidth * rows));
    for (size_t i = 0; i < band.size(); ++i)
        band[i] = static_cast<std::uint16_t>((i * 2654435761u) % 0x7c00u) | static_cast<std::uint16_t>((i % 2) << 15);
    band[0] = 0x0001;                             // smallest subnormal, 2^-24
    band[1] = 0x7bff;                             // 65504
    band[2] = 0x8000;                             // -0
    target_->uploadRgbHalf(firstRow, rows, band);

    const std::vector<float> rgb = target_->readbackRgb(firstRow, rows);
    ASSERT_EQ(rgb.size(), band.size());
    for (size_t i = 0; i < band.size(); ++i) {
        EXPECT_EQ(rgb[i], halfToFloat(band[i])) << "value " << i << " bits " << band[i];
        EXPECT_EQ(std::signbit(rgb[i]), (band[i] >> 15) != 0) << "value " << i;
    }
    EXPECT_EQ(rgb[0], std::ldexp(1.0f, -24));
    EXPECT_EQ(rgb[1], 65504.0f);

    // The whole target: the band's rows hold the halves with alpha 1, the others what was drawn.
    const std::vector<float> all = target_->readback();
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) {
            const float* p = &all[size_t(4 * (y * kWidth + x))];
            const bool inBand = y >= firstRow && y < firstRow + rows;
            const size_t b = size_t(3 * ((y - firstRow) * kWidth + x));
            EXPECT_EQ(p[0], inBand ? halfToFloat(band[b]) : float(x)) << x << "," << y;
            EXPECT_EQ(p[1], inBand ? halfToFloat(band[b + 1]) : float(y)) << x << "," << y;
            EXPECT_EQ(p[2], inBand ? halfToFloat(band[b + 2]) : float(x + y)) << x << "," << y;
            EXPECT_EQ(p[3], 1.0f) << x << "," << y;
        }
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(FloatTargetRows, RefusesRowsOutsideAndWrongSizes)
{
    EXPECT_THROW(target_->readbackRgb(-1, 2), std::invalid_argument);
    EXPECT_THROW(target_->readbackWork(8, 3), std::invalid_argument);
    EXPECT_THROW(target_->readbackRgb(0, 0), std::invalid_argument);
    EXPECT_THROW(target_->uploadRgbHalf(9, 2, std::vector<std::uint16_t>(3 * kWidth * 2)), std::invalid_argument);
    EXPECT_THROW(target_->uploadRgbHalf(0, 2, std::vector<std::uint16_t>(3 * kWidth * 2 - 1)), std::invalid_argument);
}

} // namespace
} // namespace aurorawall::gl
