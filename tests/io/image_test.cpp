#include "io/image.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

using namespace aurorawall::io;

namespace {

// A recognisable value for channel c of pixel (x, y) of a tile, counted top-down.
float code(int x, int y, int c) { return 100.0f * float(y) + 10.0f * float(x) + float(c) + 1.0f; }

} // namespace

TEST(Image, GlReadbackRowsAreFlippedToTopDown)
{
    const int w = 2, h = 3;
    std::vector<float> gl(4 * w * h);
    for (int glRow = 0; glRow < h; ++glRow) // GL row 0 is the BOTTOM row
        for (int x = 0; x < w; ++x)
            for (int c = 0; c < 4; ++c)
                gl[4 * (glRow * w + x) + c] = code(x, h - 1 - glRow, c);

    const Image image = imageFromGlReadback(w, h, gl);
    ASSERT_EQ(image.width, w);
    ASSERT_EQ(image.height, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            for (int c = 0; c < 4; ++c)
                EXPECT_EQ(image.pixel(x, y)[c], code(x, y, c)) << x << "," << y << "," << c;
    EXPECT_THROW(imageFromGlReadback(w, h, std::vector<float>(5)), std::invalid_argument);
}

TEST(Image, TileFromGlReadbackLandsAtItsOffsetAndTheRestStaysBlack)
{
    const int w = 3, h = 2, offsetX = 4, offsetY = 1;
    std::vector<float> gl(4 * w * h);
    for (int glRow = 0; glRow < h; ++glRow)
        for (int x = 0; x < w; ++x)
            for (int c = 0; c < 4; ++c)
                gl[4 * (glRow * w + x) + c] = code(x, h - 1 - glRow, c);

    Image wall(8, 5);
    pasteTile(wall, imageFromGlReadback(w, h, gl), offsetX, offsetY);

    for (int y = 0; y < wall.height; ++y)
        for (int x = 0; x < wall.width; ++x) {
            const bool inTile = x >= offsetX && x < offsetX + w && y >= offsetY && y < offsetY + h;
            for (int c = 0; c < 4; ++c)
                EXPECT_EQ(wall.pixel(x, y)[c], inTile ? code(x - offsetX, y - offsetY, c) : 0.0f)
                    << x << "," << y << "," << c;
        }
    // The top row of the tile (last GL row) is the wall row offsetY.
    EXPECT_EQ(wall.pixel(offsetX, offsetY)[0], code(0, 0, 0));
}

TEST(Image, PasteRejectsTilesThatDoNotFit)
{
    Image wall(4, 4);
    const Image tile(2, 2);
    EXPECT_NO_THROW(pasteTile(wall, tile, 2, 2));
    EXPECT_THROW(pasteTile(wall, tile, 3, 0), std::invalid_argument);
    EXPECT_THROW(pasteTile(wall, tile, 0, -1), std::invalid_argument);
}

TEST(Image, CropInvertsPaste)
{
    Image tile(3, 2);
    for (std::size_t i = 0; i < tile.rgba.size(); ++i)
        tile.rgba[i] = float(i);
    Image wall(7, 6);
    pasteTile(wall, tile, 2, 3);

    const Image back = crop(wall, 2, 3, 3, 2);
    EXPECT_EQ(back.width, 3);
    EXPECT_EQ(back.height, 2);
    EXPECT_EQ(back.rgba, tile.rgba);
    EXPECT_THROW(crop(wall, 5, 0, 3, 1), std::invalid_argument);
}

TEST(Image, CountsNonFiniteValues)
{
    Image image(2, 1);
    EXPECT_EQ(countNonFinite(image), 0u);
    image.rgba[1] = std::numeric_limits<float>::quiet_NaN();
    image.rgba[2] = std::numeric_limits<float>::infinity();
    image.rgba[7] = -std::numeric_limits<float>::infinity();
    EXPECT_EQ(countNonFinite(image), 3u);
}

TEST(Image, CompareReportsAbsoluteRelativeAndRmsDifferences)
{
    Image a(2, 1), b(2, 1); // 8 floats
    a.rgba = {1, 2, 3, 4, 0, 0, 0, 8};
    b = a;
    ImageDifference same = compareImages(a, b);
    EXPECT_EQ(same.maxAbs, 0.0);
    EXPECT_EQ(same.maxRelative, 0.0);
    EXPECT_EQ(same.rms, 0.0);

    b.rgba[0] += 2.0f; // differences: 2 and 1, six zeros
    b.rgba[5] -= 1.0f;
    const ImageDifference d = compareImages(a, b);
    EXPECT_DOUBLE_EQ(d.maxAbs, 2.0);
    EXPECT_DOUBLE_EQ(d.maxRelative, 2.0 / 8.0);
    EXPECT_DOUBLE_EQ(d.rms, std::sqrt((4.0 + 1.0) / 8.0));

    b.rgba[3] = std::numeric_limits<float>::quiet_NaN();
    EXPECT_TRUE(std::isinf(compareImages(a, b).maxAbs));
    EXPECT_TRUE(std::isinf(compareImages(a, b).maxRelative));
    EXPECT_THROW(compareImages(a, Image(1, 2)), std::invalid_argument);
}
