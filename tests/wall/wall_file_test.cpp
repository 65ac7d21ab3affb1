// Wall files: every shipped file parses to the wall it describes; every bad input gives one
// InputError naming the file and the offending line.
#include "wall/wall_file.h"

#include "common/input_error.h"
#include "wall/frustum.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace aurorawall::wall {
namespace {

Wall shipped(const std::string& name) { return loadWall(std::string(WALL_CONFIG_DIR) + "/" + name); }

TEST(WallFile, EveryShippedWallIsTomlAndLoads)
{
    int walls = 0;
    for (const auto& entry : std::filesystem::directory_iterator(WALL_CONFIG_DIR)) {
        SCOPED_TRACE(entry.path().string());
        EXPECT_EQ(entry.path().extension(), ".toml");
        const Wall wall = loadWall(entry.path().string());
        EXPECT_GE(wall.rankCount, 1);
        ++walls;
    }
    EXPECT_EQ(walls, 13);
}

TEST(WallFile, UafPowerwall)
{
    const Wall wall = shipped("uaf-powerwall.toml");
    EXPECT_NE(wall.sourceFile.find("uaf-powerwall.toml"), std::string::npos);
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
    const Wall wall = shipped("desktop-2x2.toml");
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
    const Wall wall = shipped("single.toml");
    ASSERT_EQ(wall.screens.size(), 1u);
    EXPECT_EQ(wall.rankCount, 1);
    EXPECT_EQ(wall.canvasSizePx, glm::ivec2(1280, 720));
    EXPECT_NEAR(wall.eyeMm.x, 160.0, 1e-12);
    EXPECT_NEAR(wall.eyeMm.y, 90.0, 1e-12);
}

TEST(WallFile, Desktop3x1ListsScreensExplicitly)
{
    const Wall wall = shipped("desktop-3x1.toml");
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
    const Wall wall = shipped("desktop-2x2-bezel.toml");
    EXPECT_TRUE(wall.sharedCanvas);
    EXPECT_EQ(wall.canvasSizePx, glm::ivec2(652, 372));
    EXPECT_EQ(wall.screens[3].canvasOffsetPx, glm::ivec2(332, 192));
    // Half-size windows at half the canvas positions.
    EXPECT_EQ(wall.screens[3].window.x, 166);
    EXPECT_EQ(wall.screens[3].window.y, 96);
    EXPECT_EQ(wall.screens[3].window.width, 160);
    EXPECT_EQ(wall.screens[3].window.height, 90);
}

// The walls the INI files gave before the wall files became TOML, built in code from the same
// numbers: the TOML files must give bit-identical screens, ranks, windows and frusta.
GridSpec gridSpec(int columns, int rows, glm::ivec2 px, glm::dvec2 mm, double bezelMm, double eyeZMm, int screensPerRank,
                  Stacking stacking)
{
    GridSpec g;
    g.columns = columns;
    g.rows = rows;
    g.screenPx = px;
    g.screenMm = mm;
    g.bezelMm = {bezelMm, bezelMm};
    g.eyeFromCentreMm = {0.0, 0.0, eyeZMm};
    g.screensPerRank = screensPerRank;
    g.stacking = stacking;
    return g;
}

void fullscreenOnRankMonitors(Wall& wall)
{
    for (int rank = 0; rank < wall.rankCount; ++rank) {
        const std::vector<int> owned = wall.screensOfRank(rank);
        for (std::size_t k = 0; k < owned.size(); ++k)
            wall.screens[owned[k]].window = WindowPlacement{-1, -1, -1, -1, int(k), true};
    }
}

void expectIdentical(const Wall& loaded, const Wall& expected)
{
    ASSERT_EQ(loaded.screens.size(), expected.screens.size());
    EXPECT_EQ(loaded.eyeMm, expected.eyeMm);
    EXPECT_EQ(loaded.rankCount, expected.rankCount);
    EXPECT_EQ(loaded.canvasSizePx, expected.canvasSizePx);
    EXPECT_EQ(loaded.sharedCanvas, expected.sharedCanvas);
    EXPECT_EQ(loaded.canvasTopLeftMm, expected.canvasTopLeftMm);
    EXPECT_EQ(loaded.canvasPitchMm, expected.canvasPitchMm);
    for (std::size_t i = 0; i < expected.screens.size(); ++i) {
        const Screen &a = loaded.screens[i], &b = expected.screens[i];
        SCOPED_TRACE(loaded.sourceFile + " screen " + b.name);
        EXPECT_EQ(a.name, b.name);
        EXPECT_EQ(glm::ivec2(a.widthPx, a.heightPx), glm::ivec2(b.widthPx, b.heightPx));
        EXPECT_EQ(glm::dvec2(a.widthMm, a.heightMm), glm::dvec2(b.widthMm, b.heightMm));
        EXPECT_EQ(a.lowerLeftMm, b.lowerLeftMm);
        EXPECT_EQ(a.rank, b.rank);
        EXPECT_EQ(a.canvasOffsetPx, b.canvasOffsetPx);
        EXPECT_EQ(glm::ivec4(a.window.x, a.window.y, a.window.width, a.window.height),
                  glm::ivec4(b.window.x, b.window.y, b.window.width, b.window.height));
        EXPECT_EQ(a.window.monitor, b.window.monitor);
        EXPECT_EQ(a.window.fullscreen, b.window.fullscreen);
        const Frustum fa = offAxisFrustum(a, loaded.eyeMm, 1.0, 1e5), fb = offAxisFrustum(b, expected.eyeMm, 1.0, 1e5);
        EXPECT_EQ(fa.projection, fb.projection);
        EXPECT_EQ(fa.view, fb.view);
    }
}

TEST(WallFile, ShippedGridWallsGiveTheFrustaOfTheirIniForm)
{
    const glm::ivec2 uafPx{1680, 1050};
    const glm::dvec2 uafMm{473.76, 296.1};
    Wall uaf = makeGridWall(gridSpec(5, 4, uafPx, uafMm, 42.3, 2000.0, 2, Stacking::vertical));
    fullscreenOnRankMonitors(uaf);
    expectIdentical(shipped("uaf-powerwall.toml"), uaf);

    expectIdentical(shipped("desktop-2x2.toml"),
                    makeGridWall(gridSpec(2, 2, {320, 180}, {80.0, 45.0}, 0.0, 64.26666030339516, 1, Stacking::horizontal)));
    expectIdentical(shipped("single.toml"),
                    makeGridWall(gridSpec(1, 1, {1280, 720}, {320.0, 180.0}, 0.0, 128.5333206067903, 1, Stacking::horizontal)));

    Wall bezel = makeGridWall(gridSpec(2, 2, {320, 180}, {80.0, 45.0}, 3.0, 70.0, 1, Stacking::horizontal));
    placeWindowsOnCanvas(bezel, {0, 0}, 0.5);
    expectIdentical(shipped("desktop-2x2-bezel.toml"), bezel);

    const struct {
        int ranks, columns, rows;
        double eyeZMm;
    } scaling[] = {{1, 1, 2, 453.0799551}, {2, 2, 2, 453.0799551}, {4, 4, 2, 453.0799551},
                   {8, 4, 4, 936.3652406}, {10, 5, 4, 936.3652406}};
    for (const auto& s : scaling) {
        Wall wall = makeGridWall(gridSpec(s.columns, s.rows, uafPx, uafMm, 42.3, s.eyeZMm, 2, Stacking::vertical));
        fullscreenOnRankMonitors(wall);
        EXPECT_EQ(wall.rankCount, s.ranks);
        expectIdentical(shipped("scaling-" + std::to_string(s.ranks) + ".toml"), wall);
    }
}

TEST(WallFile, ShippedScreenListGivesTheFrustaOfItsIniForm)
{
    std::vector<Screen> screens(3);
    const char* names[] = {"left", "centre", "right"};
    for (int i = 0; i < 3; ++i) {
        screens[i].name = names[i];
        screens[i].widthPx = 171;
        screens[i].heightPx = 97;
        screens[i].widthMm = 42.75;
        screens[i].heightMm = 24.25;
        screens[i].rank = i;
    }
    screens[1].lowerLeftMm.x = 42.75;
    screens[2].lowerLeftMm.x = 85.5;
    Wall wall = assembleWall(screens, {3 * 42.75 / 2, 24.25 / 2, 60.0});
    placeWindowsOnCanvas(wall);
    expectIdentical(shipped("desktop-3x1.toml"), wall);
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

const std::string iniMessage = "INI wall files are no longer read; convert to TOML (see docs/walls.md)";

struct BadInput {
    std::string file;
    std::string problem; // a fragment of the message
};

void PrintTo(const BadInput& input, std::ostream* out) { *out << input.file; }

class WallFileError : public testing::TestWithParam<BadInput> {};

TEST_P(WallFileError, NamesFileLineAndProblem)
{
    const std::string path = std::string(WALL_TEST_DATA_DIR) + "/" + GetParam().file;
    const std::string where = path + ":" + std::to_string(markedLine(path)) + ": ";
    try {
        loadWall(path);
        FAIL() << "no error for " << path;
    } catch (const common::InputError& e) {
        const std::string message = e.what();
        EXPECT_EQ(message.rfind(where, 0), 0u) << message;
        EXPECT_NE(message.find(GetParam().problem), std::string::npos) << message;
        EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    }
}

INSTANTIATE_TEST_SUITE_P(
    BadFiles, WallFileError,
    testing::Values(BadInput{"syntax-error.toml", "missing key-value separator"},
                    BadInput{"unclosed-section.toml", "invalid key"},
                    BadInput{"missing-key.toml", "missing key 'grid.width_mm'"},
                    BadInput{"unknown-key.toml", "unknown key 'grid.colums'; known keys: columns, rows"},
                    BadInput{"unknown-section.toml", "unknown key 'eyes'; known keys: grid, screen, eye, ranks, windows, projection"},
                    BadInput{"screen-unknown-key.toml", "unknown key 'screen.widht_px'"},
                    BadInput{"duplicate-key.toml", "value (\"columns\") already exists"},
                    BadInput{"duplicate-screen-name.toml", "screen.name: \"a\" is already the name of the screen on line 1"},
                    BadInput{"non-numeric.toml", "eye.z_mm: expected a number"},
                    BadInput{"non-integer.toml", "grid.columns: expected an integer"},
                    BadInput{"float-for-integer.toml", "grid.width_px: expected an integer"},
                    BadInput{"zero-size.toml", "grid.width_px: must be an integer in [1, 65536] (got 0)"},
                    BadInput{"negative-size.toml", "grid.height_mm: must be a finite number in (0, 1e+06] (got -45)"},
                    BadInput{"nan.toml", "grid.width_mm: must be a finite number"},
                    BadInput{"inf.toml", "eye.x_mm: must be a finite number"},
                    BadInput{"absurd-mm.toml", "grid.width_mm: must be a finite number in (0, 1e+06] (got 2e+06)"},
                    BadInput{"absurd-px.toml", "grid.width_px: must be an integer in [1, 65536] (got 100000)"},
                    BadInput{"overlap.toml", "screen 'right' overlaps screen 'left' (line 1) by 10 x 45 mm"},
                    BadInput{"rank-without-screen.toml", "ranks.count: 5 but the screens use ranks 0..3: rank 4 owns no screen"},
                    BadInput{"rank-count-too-small.toml", "ranks.count: 3 but the screens use ranks 0..3"},
                    BadInput{"rank-gap.toml", "screen.rank: ranks must be numbered 0..N-1 without gaps: rank 1 owns no screen"},
                    BadInput{"grid-rank-gap.toml", "ranks.per_screen: ranks must be numbered 0..N-1 without gaps: rank 2 owns no screen"},
                    BadInput{"per-screen-count.toml", "ranks.per_screen: must list 4 ranks, one per screen row-major (got 3)"},
                    BadInput{"rank-missing-on-one-screen.toml", "screen 'b' has no rank while other screens do"},
                    BadInput{"eye-on-wall.toml", "eye.z_mm: must be a finite number in (0, 1e+06] (got 0)"},
                    BadInput{"eye-behind-wall.toml", "eye.z_mm: must be a finite number in (0, 1e+06] (got -500)"},
                    BadInput{"stacking-does-not-divide.toml", "ranks.screens_per_rank: 3 must divide grid.rows = 2"},
                    BadInput{"unknown-stacking.toml", "ranks.stacking: must be one of \"horizontal\", \"vertical\" (got \"diagonal\")"},
                    BadInput{"monitors-when-windowed.toml", "windows.monitors: applies only to windows.mode = \"fullscreen\""},
                    BadInput{"monitor-when-windowed.toml", "screen.monitor: applies only to windows.mode = \"fullscreen\""},
                    BadInput{"grid-and-screens.toml", "screen: [[screen]] cannot be combined with [grid]"},
                    BadInput{"old-ini-words.toml", "old INI syntax: " + iniMessage},
                    BadInput{"old-ini-screen.toml", "old INI syntax: " + iniMessage},
                    BadInput{"old-ini-list.toml", "old INI syntax: " + iniMessage},
                    BadInput{"dome-fov-zero.toml", "projection.field_of_view_deg: must be a finite number in (0, 360] (got 0)"},
                    BadInput{"dome-fov-above-360.toml", "projection.field_of_view_deg: must be a finite number in (0, 360] (got 361)"},
                    BadInput{"negative-interocular.toml", "eye.interocular_mm: must be a finite number in [0, 1000] (got -63)"},
                    BadInput{"stereo-without-interocular.toml", "eye.interocular_mm: missing: screens show a left or right eye"},
                    BadInput{"dome-with-eyes.toml", "projection.kind: a dome master has one eye"},
                    BadInput{"tilt-on-flat.toml", "projection.tilt_deg: applies only to projection.kind = \"dome\""},
                    BadInput{"side-by-side-odd-width.toml", "screen.stereo: a side-by-side screen needs an even width_px (got 321)"},
                    BadInput{"same-eye-overlap.toml", "screen 'left2' overlaps screen 'left' (line 1) by 80 x 45 mm"}),
    [](const testing::TestParamInfo<BadInput>& info) {
        std::string name = info.param.file;
        name = name.substr(0, name.find('.'));
        for (char& c : name)
            if (c == '-')
                c = '_';
        return name;
    });

// Problems of the whole file: "file: problem", no line.
std::string wholeFileError(const std::string& path)
{
    try {
        loadWall(path);
    } catch (const common::InputError& e) {
        return e.what();
    }
    return "no error";
}

TEST(WallFileError, MissingFileNamesTheFile)
{
    const std::string path = std::string(WALL_TEST_DATA_DIR) + "/no-such-wall.toml";
    EXPECT_EQ(wholeFileError(path), path + ": cannot open the wall file");
    // A path that exists but is no file (a device that never ends, a folder) is said to be so.
    EXPECT_EQ(wholeFileError("/dev/zero"), "/dev/zero: not a regular file (a wall file is a TOML text file)");
    EXPECT_EQ(wholeFileError(WALL_TEST_DATA_DIR), std::string(WALL_TEST_DATA_DIR) +
                                                      ": not a regular file (a wall file is a TOML text file)");
}

// A line of a megabyte (the files may have 16 MiB) is an error like any other, not a stack overflow
// in a regular expression: a screen name, and a line read for the old INI form.
TEST(WallFileError, MegabyteLinesAreErrorsNamingTheLine)
{
    const std::string path = (std::filesystem::temp_directory_path() / "aurorawall-long-line.toml").string();
    const std::string megabyte(1 << 20, 'a');
    std::ofstream(path) << "[[screen]]\nname = \"" << megabyte << "?\"\n";
    EXPECT_NE(wholeFileError(path).find(path + ":2: screen.name: must be letters"), std::string::npos);
    std::ofstream(path) << "[screen." << megabyte << "]\n";
    EXPECT_EQ(wholeFileError(path).rfind(path + ":1: ", 0), 0u);
    std::filesystem::remove(path);
}

TEST(WallFileError, IniFileGetsOneLineSayingToConvert)
{
    const std::string path = std::string(WALL_TEST_DATA_DIR) + "/old-desktop-2x2.ini";
    EXPECT_EQ(wholeFileError(path), path + ": " + iniMessage);
}

TEST(WallFileError, MissingEyeConcernsTheWholeFile)
{
    const std::string path = std::string(WALL_TEST_DATA_DIR) + "/no-eye.toml";
    EXPECT_EQ(wholeFileError(path), path + ": missing table [eye] (z_mm: the eye's distance in front of the wall)");
}

TEST(WallFileError, NoScreensConcernsTheWholeFile)
{
    const std::string path = std::string(WALL_TEST_DATA_DIR) + "/no-screens.toml";
    EXPECT_EQ(wholeFileError(path), path + ": no screens: the file needs a [grid] table or [[screen]] tables");
}

} // namespace
} // namespace aurorawall::wall
