#include "io/exr.h"
#include "io/half_pixels.h"
#include "temp_dir.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

using namespace aurorawall::io;
using aurorawall::io::test::TempDir;

namespace {

Image sample()
{
    Image image(3, 2);
    const float values[] = {0.0f, 1.0f, -2.5f, 1.0f + 1.0f / 4096.0f, 1.0f + 3.0f / 4096.0f, 2.71828183f,
                            1e-8f, 65504.0f, 65519.0f, 1e6f, -1e6f, std::numeric_limits<float>::infinity(),
                            -std::numeric_limits<float>::infinity(), std::numeric_limits<float>::quiet_NaN(),
                            6.1e-5f, 1234.567f, 0.001f, 42.0f};
    for (int i = 0; i < 6; ++i)
        for (int c = 0; c < 3; ++c)
            image.rgba[4 * i + c] = values[3 * i + c];
    for (int i = 0; i < 6; ++i)
        image.rgba[4 * i + 3] = 0.5f; // not 1: alpha does not travel
    return image;
}

} // namespace

// The nearest half, ties to even (IEEE 754), after the documented clamp.
TEST(HalfPixels, RoundToNearestHalfWithTheDocumentedClamp)
{
    const Image r = roundedToHalf(sample());
    const float expected[] = {0.0f, 1.0f, -2.5f, 1.0f /* tie: even */, 1.0f + 4.0f / 4096.0f /* tie: even */,
                              2.71875f, 0.0f /* below the smallest subnormal's half */, 65504.0f, 65504.0f,
                              65504.0f, -65504.0f, 65504.0f, -65504.0f, 0.0f, 1023.0f / 16777216.0f /* subnormal */,
                              1235.0f, 0.0010004044f,
                              42.0f};
    for (int i = 0; i < 6; ++i) {
        for (int c = 0; c < 3; ++c)
            EXPECT_FLOAT_EQ(r.rgba[4 * i + c], expected[3 * i + c]) << "pixel " << i << " channel " << c;
        EXPECT_EQ(r.rgba[4 * i + 3], 1.0f);
    }
}

TEST(HalfPixels, PackedHalvesAreSixBytesAPixelAndRoundTripExactly)
{
    const Image r = roundedToHalf(sample());
    const std::vector<std::uint16_t> rgb = packRgbHalf(r);
    EXPECT_EQ(rgb.size(), 3u * 6u);
    EXPECT_EQ(packRgbHalf(unpackRgbHalf(3, 2, rgb)), rgb); // rounding twice changes nothing
    EXPECT_EQ(halfBits(1.0f), 0x3c00);
    EXPECT_EQ(halfBits(-2.0f), 0xc000);
    EXPECT_THROW(unpackRgbHalf(3, 3, rgb), std::invalid_argument);
}

// The EXR files keep exactly what the ranks exchange: the same rounding and clamp.
TEST(HalfPixels, ExrStoresTheSameHalves)
{
    TempDir dir;
    const Image original = sample();
    writeExr(dir.file("a.exr"), original);
    const Image back = readExr(dir.file("a.exr"));
    EXPECT_EQ(packRgbHalf(back), packRgbHalf(original));
}
