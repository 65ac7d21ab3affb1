// The heads-up display's text from the frame's statistics and the camera, and its bitmap font.
#include "app/hud.h"
#include "cluster/frame_message.h"
#include "render/hud_font.h"

#include <gtest/gtest.h>

#include <algorithm>

using namespace aurorawall;
using app::HudFacts;
using app::hudLines;

namespace {

HudFacts twoRanks()
{
    HudFacts f;
    f.framesPerS = 9.49;
    f.rankRenderMs = {43.2, 27.0};
    f.timeS = 120.0;
    f.altitudeKm = 0.5;
    f.latitudeDeg = 65.0;
    f.longitudeDeg = -15.25;
    return f;
}

} // namespace

TEST(Hud, LinesOfTwoRanks)
{
    // Bars: 16 cells for the slowest; 16 x 27.0 / 43.2 = 10 cells. Imbalance 43.2 / 35.1 = 1.2308.
    const std::vector<std::string> expected = {
        "FPS 9.5  T 120.00 S",
        "ALT 0.500 KM",
        "LAT 65.000 LON -15.250",
        "IMBALANCE 1.23 (MAX/MEAN)",
        "R0  ################ 43.2 MS",
        "R1  ##########       27.0 MS",
    };
    EXPECT_EQ(hudLines(twoRanks()), expected);
}

TEST(Hud, PausedAndNoFrameYet)
{
    HudFacts f;
    f.paused = true;
    f.rankRenderMs = {0.0};
    const std::vector<std::string> lines = hudLines(f);
    EXPECT_EQ(lines[0], "FPS 0.0  T 0.00 S  PAUSED");
    EXPECT_EQ(lines[3], "IMBALANCE 1.00 (MAX/MEAN)");
    EXPECT_EQ(lines[4], "R0                   0.0 MS"); // no bar without a time
}

TEST(Hud, RanksThatDoNotFitAreCounted)
{
    HudFacts f = twoRanks();
    f.rankRenderMs.assign(100, 10.0);
    f.rankRenderMs[99] = 20.0; // the slowest, not shown, still scales the bars
    const std::vector<std::string> lines = hudLines(f);
    ASSERT_EQ(lines.size(), cluster::kHudLines);
    EXPECT_EQ(lines[4], "R0  ########         10.0 MS");
    EXPECT_EQ(lines.back(), "+81 RANKS NOT SHOWN"); // 24 lines: 4 + 19 ranks + this one
}

// Every line fits the frame message and the font draws every character of it.
TEST(Hud, LinesFitTheMessageAndTheFont)
{
    HudFacts f = twoRanks();
    f.rankRenderMs.assign(12, 1234.5);
    f.timeS = -1e9;
    f.latitudeDeg = -89.999;
    f.longitudeDeg = -179.999;
    f.altitudeKm = 35786.0;
    f.paused = true;
    for (const std::string& line : hudLines(f)) {
        EXPECT_LE(line.size(), cluster::kHudColumns) << line;
        EXPECT_TRUE(std::all_of(line.begin(), line.end(), render::hasGlyph)) << line;
    }
    // The largest times a scene or the control accepts (1e15 s) keep the whole first line.
    f.framesPerS = 9999.9;
    for (const double t : {1e15, -1e15}) {
        f.timeS = t;
        const std::string first = hudLines(f).front();
        EXPECT_LE(first.size(), cluster::kHudColumns) << first;
        EXPECT_TRUE(std::all_of(first.begin(), first.end(), render::hasGlyph)) << first;
        EXPECT_EQ(first.substr(first.size() - 6), "PAUSED") << first;
    }
}

TEST(HudFont, MaskOfKnownGlyphs)
{
    // "#" is the full 5x7 block; "1" has 10 dots (HD44780 ROM: 0x04 0x0C 0x04 0x04 0x04 0x04 0x0E).
    const render::HudMask mask = render::rasterizeHud({"#1", "-"});
    ASSERT_EQ(mask.width, 2 * render::kCellWidth + 2 * render::kHudMarginPx);
    ASSERT_EQ(mask.height, 2 * render::kCellHeight + 2 * render::kHudMarginPx);
    auto dots = [&](int x0, int y0) {
        int n = 0;
        for (int y = y0; y < y0 + render::kCellHeight; ++y)
            for (int x = x0; x < x0 + render::kCellWidth; ++x)
                n += mask.coverage[y * mask.width + x] > 0.5f;
        return n;
    };
    const int m = render::kHudMarginPx;
    EXPECT_EQ(dots(m, m), 35);
    EXPECT_EQ(dots(m + render::kCellWidth, m), 10);
    EXPECT_EQ(dots(m, m + render::kCellHeight), 5);
    EXPECT_EQ(dots(m + render::kCellWidth, m + render::kCellHeight), 0); // past the end of line 2
    EXPECT_EQ(mask.coverage[(m + 3) * mask.width + m + 2], 1.0f); // inside the block
    EXPECT_EQ(mask.coverage[(m + render::kCellHeight + 3) * mask.width + m], 1.0f); // '-': row 3
    EXPECT_EQ(mask.coverage[(m + render::kCellHeight + 2) * mask.width + m], 0.0f);
    EXPECT_THROW(render::rasterizeHud({"fps"}), std::invalid_argument);
}
