// Wall files: every shipped file parses to the wall it describes; every bad input gives one
// InputError naming the file and the offending line.
#include "wall/wall_file.h"

#include "common/input_error.h"

#include <gtest/gtest.h>

#include <fstream>

namespace aurorawall::wall {
namespace {

Wall shipped(const std::string& name) { return loadWall(std::string(WALL_CONFIG_DIR) + "/" + name); }

TEST(WallFile, UafPowerwall)
{
    const Wall wall = shipped("uaf-powerwall.ini");
    EXPECT_NE(wall.sourceFile.find("uaf-powerwall.ini"), std::string::npos);
    ASSERT_EQ(wall.screens.size(), 20u);
    EXPECT_EQ(wall.rankCount, 10);
    EXPECT_TRUE(wall.sharedCanvas);
    EXPECT_EQ(wall.canvasSizePx, glm::ivec2(9000, 4650));
    const Screen& row1col2 = wall.screens[1 * 5 + 2];
    EXPECT_EQ(row1col2.canvasOffsetPx, glm::ivec2(3660, 1200));
    EXPECT_EQ(row1col2.widthPx, 1680);
    EXPECT_EQ(row1col2.heightPx, 1050);
    // Rank 0 drives the top two screens of column 0, stacked: same x, the second just below.
    const std::vector<int> rank0 = wall.screensOfRank(0);
    ASSERT_EQ(rank0.size(), 2u);
    const Screen &upper = wall.screens[rank0[0]], &lower = wall.screens[rank0[1]];
    EXPECT_EQ(upper.canvasOffsetPx, glm::ivec2(0, 0));
    EXPECT_EQ(lower.canvasOffsetPx, glm::ivec2(0, 1200));
    EXPECT_NEAR(upper.lowerLeftMm.y - lower.upperLeft().y, 150 * 0.282, 1e-9);
    for (int rank = 0; rank < 10; ++rank)
        EXPECT_EQ(wall.screensOfRank(rank).size(), 2u);
    // Ranks form 5 columns x 2 rows.
    EXPECT_EQ(wall.screens[wall.screensOfRank(7)[0]].canvasOffsetPx, glm::ivec2(2 * 1830, 2 * 1200));
    // Fullscreen, each host's upper screen on monitor 0 and lower on monitor 1.
    EXPECT_TRUE(upper.window.fullscreen);
    EXPECT_EQ(upper.window.monitor, 0);
    EXPECT_EQ(lower.window.monitor, 1);
    EXPECT_NEAR(wall.eyeMm.x, 9000 * 0.282 / 2, 1e-9);
    EXPECT_NEAR(wall.eyeMm.y, 4650 * 0.282 / 2, 1e-9);
    EXPECT_EQ(wall.eyeMm.z, 2000.0);
}

TEST(WallFile, Desktop2x2)
{
    const Wall wall = shipped("desktop-2x2.ini");
    ASSERT_EQ(wall.screens.size(), 4u);
    EXPECT_EQ(wall.rankCount, 4);
    EXPECT_TRUE(wall.sharedCanvas);
    EXPECT_EQ(wall.canvasSizePx, glm::ivec2(640, 360));
    EXPECT_EQ(wall.screens[3].canvasOffsetPx, glm::ivec2(320, 180));
    EXPECT_EQ(wall.screens[3].rank, 3);
    EXPECT_FALSE(wall.screens[3].window.fullscreen);
    EXPECT_EQ(wall.screens[3].window.x, 320);
    EXPECT_EQ(wall.screens[3].window.y, 180);
    EXPECT_EQ(wall.screens[3].window.width, 320);
}

TEST(WallFile, Single)
{
    const Wall wall = shipped("single.ini");
    ASSERT_EQ(wall.screens.size(), 1u);
    EXPECT_EQ(wall.rankCount, 1);
    EXPECT_EQ(wall.canvasSizePx, glm::ivec2(1280, 720));
    EXPECT_NEAR(wall.eyeMm.x, 160.0, 1e-12);
    EXPECT_NEAR(wall.eyeMm.y, 90.0, 1e-12);
}

TEST(WallFile, Desktop3x1ListsScreensExplicitly)
{
    const Wall wall = shipped("desktop-3x1.ini");
    ASSERT_EQ(wall.screens.size(), 3u);
    EXPECT_EQ(wall.screens[0].name, "left");
    EXPECT_EQ(wall.screens[1].name, "centre");
    EXPECT_EQ(wall.screens[2].name, "right");
    EXPECT_EQ(wall.rankCount, 3);
    EXPECT_TRUE(wall.sharedCanvas);
    EXPECT_EQ(wall.canvasSizePx, glm::ivec2(513, 97));
    EXPECT_EQ(wall.screens[2].canvasOffsetPx, glm::ivec2(342, 0));
    EXPECT_NEAR(wall.eyeMm.x, 3 * 42.75 / 2, 1e-12);
}

TEST(WallFile, Desktop2x2Bezel)
{
    const Wall wall = shipped("desktop-2x2-bezel.ini");
    EXPECT_TRUE(wall.sharedCanvas);
    EXPECT_EQ(wall.canvasSizePx, glm::ivec2(652, 372));
    EXPECT_EQ(wall.screens[3].canvasOffsetPx, glm::ivec2(332, 192));
    // Half-size windows at half the canvas positions.
    EXPECT_EQ(wall.screens[3].window.x, 166);
    EXPECT_EQ(wall.screens[3].window.y, 96);
    EXPECT_EQ(wall.screens[3].window.width, 160);
    EXPECT_EQ(wall.screens[3].window.height, 90);
}

// The line a bad-input file marks with "# <- error"; the error must name it.
int markedLine(const std::string& path)
{
    std::ifstream in(path);
    std::string line;
    for (int n = 1; std::getline(in, line); ++n)
        if (line.find("# <- error") != std::string::npos)
            return n;
    ADD_FAILURE() << path << " marks no line";
    return -1;
}

struct BadInput {
    const char* file;
    const char* problem; // a fragment of the message
};

class WallFileError : public testing::TestWithParam<BadInput> {};

TEST_P(WallFileError, NamesFileLineAndProblem)
{
    const std::string path = std::string(WALL_TEST_DATA_DIR) + "/" + GetParam().file;
    const std::string where = path + ":" + std::to_string(markedLine(path)) + ": ";
    try {
        loadWall(path);
        FAIL() << "no error for " << path;
    } catch (const InputError& e) {
        const std::string message = e.what();
        EXPECT_EQ(message.rfind(where, 0), 0u) << message;
        EXPECT_NE(message.find(GetParam().problem), std::string::npos) << message;
        EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    }
}

INSTANTIATE_TEST_SUITE_P(
    BadFiles, WallFileError,
    testing::Values(BadInput{"syntax-error.ini", "syntax error"}, BadInput{"unclosed-section.ini", "syntax error"},
                    BadInput{"missing-key.ini", "[grid] needs width_mm"}, BadInput{"unknown-key.ini", "unknown key 'colums'"},
                    BadInput{"unknown-section.ini", "unknown section [eyes]"},
                    BadInput{"duplicate-key.ini", "duplicate key grid.columns"},
                    BadInput{"non-numeric.ini", "eye.z_mm must be a number"},
                    BadInput{"non-integer.ini", "grid.columns must be an integer"},
                    BadInput{"zero-size.ini", "grid.width_px must be >= 1"}, BadInput{"negative-size.ini", "grid.height_mm must be > 0"},
                    BadInput{"nan.ini", "grid.width_mm must be a finite number"},
                    BadInput{"inf.ini", "eye.x_mm must be a finite number"},
                    BadInput{"absurd-mm.ini", "grid.width_mm must be > 0 and <= 1e+06"},
                    BadInput{"absurd-px.ini", "grid.width_px must be >= 1 and <= 65536"},
                    BadInput{"overlap.ini", "screen 'right' overlaps screen 'left'"},
                    BadInput{"rank-without-screen.ini", "rank 4 owns no screen"},
                    BadInput{"rank-gap.ini", "rank 1 owns no screen"}, BadInput{"grid-rank-gap.ini", "rank 2 owns no screen"},
                    BadInput{"rank-missing-on-one-screen.ini", "[screen.b] has no rank"},
                    BadInput{"eye-on-wall.ini", "eye.z_mm must be > 0"}, BadInput{"eye-behind-wall.ini", "eye.z_mm must be > 0"},
                    BadInput{"stacking-does-not-divide.ini", "must divide grid.rows = 2"},
                    BadInput{"monitors-when-windowed.ini", "windows.monitors applies only to windows.mode = fullscreen"},
                    BadInput{"grid-and-screens.ini", "cannot be combined with [grid]"}),
    [](const testing::TestParamInfo<BadInput>& info) {
        std::string name = info.param.file;
        name = name.substr(0, name.find('.'));
        for (char& c : name)
            if (c == '-')
                c = '_';
        return name;
    });

TEST(WallFileError, MissingFileNamesTheFile)
{
    const std::string path = std::string(WALL_TEST_DATA_DIR) + "/no-such-wall.ini";
    try {
        loadWall(path);
        FAIL();
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()), path + ": cannot open the wall file");
    }
}

} // namespace
} // namespace aurorawall::wall
