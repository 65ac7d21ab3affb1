// The wall model: grid layout, rank assignment, the wall canvas.
#include "wall/wall.h"

#include <gtest/gtest.h>

#include <stdexcept>

namespace aurorawall::wall {
namespace {

GridSpec uafGrid()
{
    GridSpec g;
    g.columns = 5;
    g.rows = 4;
    g.screenPx = {1680, 1050};
    g.screenMm = {1680 * 0.282, 1050 * 0.282};
    g.bezelMm = {150 * 0.282, 150 * 0.282};
    g.screensPerRank = 2;
    g.stacking = Stacking::vertical;
    return g;
}

TEST(Wall, GridCanvasStepsByScreenPlusBezel)
{
    const Wall wall = makeGridWall(uafGrid());
    ASSERT_EQ(wall.screens.size(), 20u);
    EXPECT_TRUE(wall.sharedCanvas);
    EXPECT_EQ(wall.canvasSizePx, glm::ivec2(9000, 4650));
    for (int row = 0; row < 4; ++row)
        for (int column = 0; column < 5; ++column)
            EXPECT_EQ(wall.screens[row * 5 + column].canvasOffsetPx, glm::ivec2(1830 * column, 1200 * row));
    EXPECT_NEAR(wall.canvasPitchMm.x, 0.282, 1e-12);
}

TEST(Wall, VerticalStackingGivesEachRankAColumnPair)
{
    const Wall wall = makeGridWall(uafGrid());
    EXPECT_EQ(wall.rankCount, 10);
    for (int rank = 0; rank < 10; ++rank) {
        const std::vector<int> owned = wall.screensOfRank(rank);
        ASSERT_EQ(owned.size(), 2u);
        const int column = rank % 5, rankRow = rank / 5;
        EXPECT_EQ(owned[0], (2 * rankRow) * 5 + column);
        EXPECT_EQ(owned[1], (2 * rankRow + 1) * 5 + column);
    }
}

TEST(Wall, HorizontalStackingPairsNeighbouringColumns)
{
    GridSpec g;
    g.columns = 4;
    g.rows = 2;
    g.screensPerRank = 2;
    const Wall wall = makeGridWall(g);
    EXPECT_EQ(wall.rankCount, 4);
    EXPECT_EQ(wall.screensOfRank(0), (std::vector<int>{0, 1}));
    EXPECT_EQ(wall.screensOfRank(1), (std::vector<int>{2, 3}));
    EXPECT_EQ(wall.screensOfRank(3), (std::vector<int>{6, 7}));
    g.screensPerRank = 3;
    EXPECT_THROW(makeGridWall(g), std::invalid_argument);
}

TEST(Wall, DefaultIsOneRankPerScreenRowMajor)
{
    GridSpec g;
    g.columns = 3;
    g.rows = 2;
    const Wall wall = makeGridWall(g);
    for (int i = 0; i < 6; ++i)
        EXPECT_EQ(wall.screens[i].rank, i);
    EXPECT_EQ(wall.screens[4].name, "r1c1");
    // Row 0 is at the top: its lower-left y is one screen height above row 1's.
    EXPECT_DOUBLE_EQ(wall.screens[0].lowerLeftMm.y, 1.0);
    EXPECT_DOUBLE_EQ(wall.screens[3].lowerLeftMm.y, 0.0);
}

TEST(Wall, EyeIsRelativeToTheWallCentre)
{
    GridSpec g = uafGrid();
    g.eyeFromCentreMm = {10.0, -20.0, 2000.0};
    const Wall wall = makeGridWall(g);
    EXPECT_NEAR(wall.eyeMm.x, 9000 * 0.282 / 2 + 10.0, 1e-9);
    EXPECT_NEAR(wall.eyeMm.y, 4650 * 0.282 / 2 - 20.0, 1e-9);
    EXPECT_EQ(wall.eyeMm.z, 2000.0);
}

TEST(Wall, DifferentPitchesGiveAnUnsharedCanvasWithoutOverlap)
{
    Screen coarse;
    coarse.name = "coarse";
    coarse.widthPx = 100;
    coarse.heightPx = 100;
    coarse.widthMm = coarse.heightMm = 50.0; // 0.5 mm pitch
    Screen fine = coarse;
    fine.name = "fine";
    fine.widthPx = fine.heightPx = 167;      // 0.2994 mm pitch
    fine.lowerLeftMm = {50.0, 0.0};
    fine.rank = 1;
    const Wall wall = assembleWall({coarse, fine}, {50.0, 25.0, 100.0});
    EXPECT_FALSE(wall.sharedCanvas);
    EXPECT_EQ(wall.rankCount, 2);
    EXPECT_NEAR(wall.canvasPitchMm.x, 50.0 / 167, 1e-15);
    EXPECT_EQ(wall.screens[1].canvasOffsetPx, glm::ivec2(167, 0));
    EXPECT_GE(wall.screens[1].canvasOffsetPx.x, wall.screens[0].canvasOffsetPx.x + wall.screens[0].widthPx);
    EXPECT_EQ(wall.canvasSizePx, glm::ivec2(334, 167));
}

TEST(Wall, FractionalPixelOffsetGivesAnUnsharedCanvas)
{
    GridSpec g;
    g.columns = 2;
    g.screenPx = {100, 100};
    g.screenMm = {100.0, 100.0};
    g.bezelMm = {2.5, 0.0}; // two and a half pixels
    EXPECT_FALSE(makeGridWall(g).sharedCanvas);
    g.bezelMm = {3.0, 0.0};
    const Wall whole = makeGridWall(g);
    EXPECT_TRUE(whole.sharedCanvas);
    EXPECT_EQ(whole.canvasSizePx, glm::ivec2(203, 100));
}

TEST(Wall, SingleScreenEquivalentCoversTheCanvas)
{
    const Wall wall = makeGridWall(uafGrid());
    const Wall single = singleScreenEquivalent(wall);
    ASSERT_EQ(single.screens.size(), 1u);
    EXPECT_TRUE(single.sharedCanvas);
    EXPECT_EQ(single.canvasSizePx, wall.canvasSizePx);
    EXPECT_EQ(single.eyeMm, wall.eyeMm);
    EXPECT_NEAR(single.canvasTopLeftMm.x, wall.canvasTopLeftMm.x, 1e-9);
    EXPECT_NEAR(single.canvasTopLeftMm.y, wall.canvasTopLeftMm.y, 1e-9);
}

TEST(Wall, WindowsFollowTheCanvasScaled)
{
    Wall wall = makeGridWall(uafGrid());
    placeWindowsOnCanvas(wall, {100, 50}, 0.1);
    const Screen& s = wall.screens[7]; // row 1, column 2
    EXPECT_EQ(s.window.x, 100 + 366);
    EXPECT_EQ(s.window.y, 50 + 120);
    EXPECT_EQ(s.window.width, 168);
    EXPECT_EQ(s.window.height, 105);
    EXPECT_FALSE(s.window.fullscreen);
}

TEST(Wall, AbsurdCanvasIsRejected)
{
    Screen s;
    s.widthPx = s.heightPx = 1000;
    s.widthMm = s.heightMm = 1.0;
    Screen far = s;
    far.lowerLeftMm = {1e5, 0.0};
    EXPECT_THROW(assembleWall({s, far}, {0, 0, 1}), std::invalid_argument);
    EXPECT_THROW(assembleWall({}, {0, 0, 1}), std::invalid_argument);
}

} // namespace
} // namespace aurorawall::wall
