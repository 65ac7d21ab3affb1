#include "io/exr.h"
#include "temp_dir.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

using namespace aurorawall::io;
using aurorawall::io::test::TempDir;

namespace {

constexpr float halfMax = 65504.0f;
constexpr float inf = std::numeric_limits<float>::infinity();
constexpr float quietNan = std::numeric_limits<float>::quiet_NaN();

} // namespace

TEST(Exr, RoundTripKeepsValuesWithinHalfPrecision)
{
    TempDir dir;
    Image image(3, 2);
    image.rgba = {0.0f,   1e-3f,  0.1234f, 1.0f,  //
                  0.5f,   1.0f,   2.71828f, 0.25f, //
                  42.0f,  1234.5f, 1e4f,    0.0f,  //
                  6e4f,   -2.5f,  0.75f,   0.5f,  //
                  1e5f / 2, 7.0f, 0.01f,   1.0f,  //
                  2e-2f,  9.99f,  123.0f,  0.75f};
    writeExr(dir.file("a.exr"), image, ExrChannels::RGBA);
    const Image back = readExr(dir.file("a.exr"));
    ASSERT_EQ(back.width, 3);
    ASSERT_EQ(back.height, 2);
    for (std::size_t i = 0; i < image.rgba.size(); ++i)
        EXPECT_NEAR(back.rgba[i], image.rgba[i], 1e-3 * std::abs(image.rgba[i])) << "float " << i;
}

TEST(Exr, RgbFileReadsWithAlphaOneAndKeepsRowOrder)
{
    TempDir dir;
    Image image(1, 3);
    for (int y = 0; y < 3; ++y)
        image.pixel(0, y)[0] = float(y + 1); // red grows downwards
    writeExr(dir.file("a.exr"), image);
    const Image back = readExr(dir.file("a.exr"));
    for (int y = 0; y < 3; ++y) {
        EXPECT_EQ(back.pixel(0, y)[0], float(y + 1));
        EXPECT_EQ(back.pixel(0, y)[3], 1.0f);
    }
}

TEST(Exr, LargeValuesClampToHalfMaxAndNanBecomesZero)
{
    TempDir dir;
    Image image(2, 1);
    image.rgba = {1e5f, 1e30f, inf, quietNan, //
                  -1e5f, -inf, halfMax, 65519.0f};
    writeExr(dir.file("a.exr"), image, ExrChannels::RGBA);
    const Image back = readExr(dir.file("a.exr"));
    EXPECT_EQ(countNonFinite(back), 0u);
    const float expected[] = {halfMax, halfMax, halfMax, 0.0f, -halfMax, -halfMax, halfMax, halfMax};
    for (std::size_t i = 0; i < 8; ++i)
        EXPECT_EQ(back.rgba[i], expected[i]) << "float " << i;
}

TEST(Exr, RejectsEmptyAndInconsistentImages)
{
    TempDir dir;
    EXPECT_THROW(writeExr(dir.file("a.exr"), Image()), std::invalid_argument);
    Image broken(2, 2);
    broken.rgba.pop_back();
    EXPECT_THROW(writeExr(dir.file("a.exr"), broken), std::invalid_argument);
    EXPECT_TRUE(dir.entries().empty());
}

TEST(Exr, ReadingAMissingOrBrokenFileThrowsNamingIt)
{
    TempDir dir;
    try {
        readExr(dir.file("none.exr"));
        FAIL() << "no exception";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("none.exr"), std::string::npos) << e.what();
    }
}
