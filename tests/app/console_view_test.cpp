// The console's preview of the gathered wall (app/console_view.h): box means, rows turned bottom-up.
#include "app/console_view.h"

#include "wall/wall_file.h"

#include <gtest/gtest.h>

namespace aurorawall::app {
namespace {

// A canvas whose pixel (x, y) is (x, y, x + 10 y, 1).
io::Image ramp(int w, int h)
{
    io::Image image(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            float* p = image.pixel(x, y);
            p[0] = float(x), p[1] = float(y), p[2] = float(x + 10 * y), p[3] = 1.0f;
        }
    return image;
}

TEST(ConsoleView, HeightKeepsTheWallsAspect)
{
    EXPECT_EQ(consoleHeightPx(1920, 1080), 270);
    EXPECT_EQ(consoleHeightPx(3 * 1920 + 2 * 40, 1080), 89); // 480 x 1080 / 5840 = 88.77
}

TEST(ConsoleView, BoxMeansBottomUp)
{
    // 6x4 into 3x2: each console pixel the mean of a 2x2 box; console row 0 (bottom) is canvas rows 2-3.
    const std::vector<float> t = previewTexels(ramp(6, 4), 3, 2);
    ASSERT_EQ(t.size(), 3u * 2u * 4u);
    const float* bottomLeft = &t[0];
    EXPECT_EQ(bottomLeft[0], 0.5f);  // x 0, 1
    EXPECT_EQ(bottomLeft[1], 2.5f);  // y 2, 3
    EXPECT_EQ(bottomLeft[2], 25.5f); // x + 10 y
    EXPECT_EQ(bottomLeft[3], 1.0f);
    const float* topRight = &t[4 * (1 * 3 + 2)];
    EXPECT_EQ(topRight[0], 4.5f);
    EXPECT_EQ(topRight[1], 0.5f);
}

TEST(ConsoleView, EnlargingTakesTheNearestPixel)
{
    const std::vector<float> t = previewTexels(ramp(2, 1), 4, 1);
    EXPECT_EQ(t[0 * 4], 0.0f);
    EXPECT_EQ(t[1 * 4], 0.0f);
    EXPECT_EQ(t[2 * 4], 1.0f);
    EXPECT_EQ(t[3 * 4], 1.0f);
    EXPECT_THROW(previewTexels(io::Image(), 4, 1), std::invalid_argument);
}

// Windowed walls: the console opens below the lowest window, at the leftmost x, so it covers none.
TEST(ConsoleView, OpensBelowTheWallsWindows)
{
    const wall::Wall desktop = wall::loadWall(AW_WALLS_DIR "/desktop-2x2.toml"); // 2x2 windows of 320x180
    EXPECT_EQ(consolePositionPx(desktop), glm::ivec2(0, 360));
    const wall::Wall bezel = wall::loadWall(AW_WALLS_DIR "/desktop-2x2-bezel.toml"); // half-size windows
    int bottom = 0;
    for (const wall::Screen& s : bezel.screens)
        bottom = std::max(bottom, s.window.y + s.window.height);
    EXPECT_GT(bottom, 0);
    EXPECT_EQ(consolePositionPx(bezel), glm::ivec2(0, bottom));
    EXPECT_LT(bottom, 360); // the bezel wall's canvas is taller than 360 px, its windows half size
}

// Fullscreen walls: the window system places the console.
TEST(ConsoleView, FullscreenWallsLeaveTheConsoleToTheWindowSystem)
{
    EXPECT_EQ(consolePositionPx(wall::loadWall(AW_WALLS_DIR "/uaf-powerwall.toml")), glm::ivec2(-1, -1));
}

} // namespace
} // namespace aurorawall::app
