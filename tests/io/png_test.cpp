#include "io/png.h"
#include "temp_dir.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

using namespace aurorawall::io;
using aurorawall::io::test::TempDir;

TEST(Png, WritesTheToneMappedPixelsAsSrgbBytesTopDown)
{
    TempDir dir;
    Image image(2, 2);
    const float radiance[4][3] = {{0, 0, 0}, {1, 0.5f, 0.0031308f}, {4, 4, 4}, {-1, 0.02f, 1e6f}};
    for (int i = 0; i < 4; ++i)
        for (int c = 0; c < 3; ++c)
            image.rgba[4 * i + c] = radiance[i][c];
    for (const ToneMap toneMap : {ToneMap{ToneMap::Curve::AcesFilmic, 0.7}, ToneMap{ToneMap::Curve::MagnitudeGamma, 1.0}}) {
        writePng(dir.file("a.png"), image, toneMap);
        const Image back = readPng8(dir.file("a.png"));
        ASSERT_EQ(back.width, 2);
        ASSERT_EQ(back.height, 2);
        for (int i = 0; i < 4; ++i) {
            const glm::dvec3 display =
                toneMapPixel(glm::dvec3(radiance[i][0], radiance[i][1], radiance[i][2]), toneMap);
            for (int c = 0; c < 3; ++c)
                EXPECT_EQ(std::lround(255 * back.rgba[4 * i + c]), std::lround(255 * display[c]))
                    << "pixel " << i << " channel " << c;
            EXPECT_EQ(back.rgba[4 * i + 3], 1.0f); // opaque
        }
    }
    EXPECT_EQ(dir.entries(), std::vector<std::string>{"a.png"});
}

TEST(Png, RejectsEmptyImagesAndUnreadableFiles)
{
    TempDir dir;
    EXPECT_THROW(writePng(dir.file("a.png"), Image(), ToneMap{}), std::invalid_argument);
    EXPECT_THROW(readPng8(dir.file("none.png")), std::runtime_error);
    EXPECT_TRUE(dir.entries().empty());
}
