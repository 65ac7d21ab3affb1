#include "wall/wall_file.h"

#include "common/input_error.h"
#include "config/toml_reader.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <optional>
#include <regex>
#include <set>
#include <sstream>
#include <stdexcept>

namespace aurorawall::wall {
namespace {

using config::TableReader;
using config::TomlValue;

// Bounds that catch unit mix-ups (metres for millimetres, a canvas for a screen) and garbage.
constexpr double maxMm = 1e6;
constexpr int maxPx = 65536;
constexpr int maxGridSide = 1024;
constexpr int maxRank = 65535;
constexpr int maxMonitor = 63;
constexpr double maxWindowScale = 16.0;

const std::vector<std::string> topKeys = {"grid", "screen", "eye", "ranks", "windows", "projection"};
const std::vector<std::string> gridKeys = {"columns",  "rows",      "width_px",           "height_px",
                                           "width_mm", "height_mm", "bezel_horizontal_mm", "bezel_vertical_mm"};
const std::vector<std::string> screenKeys = {"name", "width_px", "height_px", "width_mm",    "height_mm",  "x_mm",
                                             "y_mm", "rank",     "monitor",   "window_x_px", "window_y_px", "eye", "stereo"};
const std::vector<std::string> eyeKeys = {"x_mm", "y_mm", "z_mm", "interocular_mm"};
const std::vector<std::string> projectionKeys = {"kind", "field_of_view_deg", "tilt_deg"};
// Human interocular distances are 50-80 mm; the bound only catches unit mix-ups.
constexpr double maxInterocularMm = 1000.0;
const std::vector<std::string> rankKeys = {"screens_per_rank", "stacking", "per_screen", "count"};
const std::vector<std::string> windowKeys = {"mode", "origin_x_px", "origin_y_px", "scale", "monitors"};

const std::string convertHint = "INI wall files are no longer read; convert to TOML (see docs/walls.md)";

std::string show(double x)
{
    std::ostringstream out;
    out << x;
    return out.str();
}

// The old INI form, recognised by the lines TOML reads differently or not at all: "[screen.NAME]"
// sections (TOML: a nested table, not a screen list), unquoted words ("mode = windowed") and
// space-separated lists ("per_screen = 0 1 2 3"). Returns the first such line, or 0. Only a line's
// first 256 bytes are matched: std::regex recurses once per character and overflows the stack on
// a line of a megabyte.
int oldIniLine(const std::string& path)
{
    static const std::regex iniOnly(R"(\s*(\[screen\.[^\]]*\]|(mode|stacking)\s*=\s*[A-Za-z]|(per_screen|monitors)\s*=\s*[0-9]).*)");
    std::ifstream in(path);
    std::string text;
    for (int line = 1; std::getline(in, text); ++line)
        if (std::regex_match(text.substr(0, 256), iniOnly))
            return line;
    return 0;
}

void forbid(const TableReader& t, const std::string& key, const std::string& reason)
{
    if (t.has(key))
        t.fail(key, reason);
}

// Explicit ranks must be 0..N-1 without gaps. Returns the index of the first screen whose rank is
// the one above a gap, and the missing rank.
std::optional<std::pair<std::size_t, int>> rankGap(const std::vector<int>& ranks)
{
    const std::set<int> used(ranks.begin(), ranks.end());
    for (int r = 0; r < *used.rbegin(); ++r) {
        if (used.count(r))
            continue;
        const int above = *used.upper_bound(r);
        for (std::size_t i = 0; i < ranks.size(); ++i)
            if (ranks[i] == above)
                return std::make_pair(i, r);
    }
    return std::nullopt;
}

std::string gapProblem(int missing, int above)
{
    return "ranks must be numbered 0..N-1 without gaps: rank " + std::to_string(missing) + " owns no screen, but rank " +
           std::to_string(above) + " does";
}

// One parsed wall file: its tables, read once each through a TableReader, and the assembly of the wall.
class WallFile {
public:
    WallFile(const config::TomlFile& root, const std::string& path)
        : path_(path), top_(root.root, path, "", root.lines), ranks_(top_.optionalTable("ranks")), windows_(top_.optionalTable("windows"))
    {
    }
    Wall load();

private:
    [[noreturn]] void failFile(const std::string& problem) const { throw common::inputError(path_, 0, problem); }
    glm::dvec3 eyeOffset() const;
    Wall gridWall();
    Wall screenListWall();
    Screen readScreen(const TableReader& s, const std::vector<Screen>& earlier) const;
    void checkOverlaps(const Screen& screen, const TableReader& s, const std::vector<Screen>& earlier) const;
    void numberRanks(std::vector<Screen>& screens, bool anyRank, std::optional<std::size_t> firstWithoutRank) const;
    void checkRankCount(const Wall& wall) const;
    void placeWindows(Wall& wall) const;
    void readProjection(Wall& wall) const;

    std::string path_;
    TableReader top_;
    TableReader ranks_, windows_;
    std::vector<TableReader> screens_; // the [[screen]] tables in file order; empty for a grid
};

Wall WallFile::load()
{
    top_.rejectKeysOutside(topKeys);
    ranks_.rejectKeysOutside(rankKeys);
    windows_.rejectKeysOutside(windowKeys);
    if (top_.has("grid") && top_.has("screen"))
        top_.fail("screen", "[[screen]] cannot be combined with [grid]: describe the wall as a grid or as a list of screens");
    if (!top_.has("grid") && !top_.has("screen"))
        failFile("no screens: the file needs a [grid] table or [[screen]] tables");
    Wall wall = top_.has("grid") ? gridWall() : screenListWall();
    checkRankCount(wall);
    placeWindows(wall);
    readProjection(wall);
    return wall;
}

// The eye relative to the centre of the screens' bounding box; z is its distance from the wall.
// A dome master does not use the eye: its [eye] may be left out.
glm::dvec3 WallFile::eyeOffset() const
{
    const TableReader projection = top_.optionalTable("projection");
    if (!top_.has("eye") && projection.has("kind") && projection.string("kind") == "dome")
        return {0.0, 0.0, 1.0};
    if (!top_.has("eye"))
        failFile("missing table [eye] (z_mm: the eye's distance in front of the wall)");
    const TableReader eye = top_.table("eye");
    eye.rejectKeysOutside(eyeKeys);
    return {eye.number("x_mm", -maxMm, maxMm, 0.0), eye.number("y_mm", -maxMm, maxMm, 0.0),
            eye.numberAbove("z_mm", 0.0, maxMm)};
}

Wall WallFile::gridWall()
{
    const TableReader g = top_.table("grid");
    g.rejectKeysOutside(gridKeys);
    GridSpec grid;
    grid.columns = g.integer("columns", 1, maxGridSide);
    grid.rows = g.integer("rows", 1, maxGridSide);
    grid.screenPx = {g.integer("width_px", 1, maxPx), g.integer("height_px", 1, maxPx)};
    grid.screenMm = {g.numberAbove("width_mm", 0.0, maxMm), g.numberAbove("height_mm", 0.0, maxMm)};
    grid.bezelMm = {g.number("bezel_horizontal_mm", 0.0, maxMm, 0.0), g.number("bezel_vertical_mm", 0.0, maxMm, 0.0)};
    grid.eyeFromCentreMm = eyeOffset();

    const bool perScreen = ranks_.has("per_screen");
    if (perScreen) {
        forbid(ranks_, "screens_per_rank", "cannot be combined with ranks.per_screen");
        forbid(ranks_, "stacking", "cannot be combined with ranks.per_screen");
    } else {
        const bool vertical = ranks_.choice("stacking", {"horizontal", "vertical"}, 0) == 1;
        grid.stacking = vertical ? Stacking::vertical : Stacking::horizontal;
        grid.screensPerRank = ranks_.integer("screens_per_rank", 1, maxRank, 1);
        const int stacked = vertical ? grid.rows : grid.columns;
        if (stacked % grid.screensPerRank != 0)
            ranks_.fail("screens_per_rank", std::to_string(grid.screensPerRank) + " must divide grid." +
                                                (vertical ? "rows = " : "columns = ") + std::to_string(stacked) +
                                                " (stacking = " + (vertical ? "vertical" : "horizontal") + ")");
    }
    Wall wall;
    try {
        wall = makeGridWall(grid);
        if (perScreen) {
            const std::vector<int> ranks = ranks_.integers("per_screen", 0, maxRank);
            if (ranks.size() != wall.screens.size())
                ranks_.fail("per_screen", "must list " + std::to_string(wall.screens.size()) +
                                              " ranks, one per screen row-major (got " + std::to_string(ranks.size()) + ")");
            if (const auto gap = rankGap(ranks))
                ranks_.fail("per_screen", gapProblem(gap->second, ranks[gap->first]));
            for (std::size_t i = 0; i < ranks.size(); ++i)
                wall.screens[i].rank = ranks[i];
            wall = assembleWall(std::move(wall.screens), wall.eyeMm);
        }
    } catch (const std::invalid_argument& e) {
        failFile(e.what());
    }
    wall.sourceFile = path_;
    return wall;
}

Wall WallFile::screenListWall()
{
    forbid(ranks_, "stacking", "applies only to a [grid]");
    forbid(ranks_, "per_screen", "applies only to a [grid]; give each [[screen]] a rank");
    screens_ = top_.arrayOfTables("screen");
    std::vector<Screen> screens;
    bool anyRank = false;
    std::optional<std::size_t> firstWithoutRank;
    for (const TableReader& s : screens_) {
        Screen screen = readScreen(s, screens);
        checkOverlaps(screen, s, screens);
        if (s.has("rank")) {
            screen.rank = s.integer("rank", 0, maxRank);
            anyRank = true;
        } else if (!firstWithoutRank) {
            firstWithoutRank = screens.size();
        }
        screens.push_back(screen);
    }
    numberRanks(screens, anyRank, firstWithoutRank);

    glm::dvec2 lo = screens.front().lowerLeftMm, hi = lo;
    for (const Screen& screen : screens) {
        lo = glm::min(lo, screen.lowerLeftMm);
        hi = glm::max(hi, glm::dvec2(screen.upperRight()));
    }
    const glm::dvec3 eyeMm = glm::dvec3((lo + hi) / 2.0, 0.0) + eyeOffset();
    try {
        return assembleWall(std::move(screens), eyeMm, path_);
    } catch (const std::invalid_argument& e) {
        failFile(e.what());
    }
}

// One [[screen]] table without its rank: its name (unique among the earlier screens), size, place
// and eye.
Screen WallFile::readScreen(const TableReader& s, const std::vector<Screen>& earlier) const
{
    s.rejectKeysOutside(screenKeys);
    Screen screen;
    screen.name = s.string("name");
    // The name becomes part of file names (tile-NAME.exr) and window titles.
    const auto fileNameSafe = [](char c) {
        return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_' || c == '.' ||
               c == '-';
    };
    if (screen.name.empty() || !std::all_of(screen.name.begin(), screen.name.end(), fileNameSafe))
        s.fail("name", "must be letters, digits, '_', '.' or '-' (got \"" + common::echoedInput(screen.name) + "\")");
    for (std::size_t j = 0; j < earlier.size(); ++j)
        if (earlier[j].name == screen.name)
            s.fail("name", "\"" + common::echoedInput(screen.name) + "\" is already the name of the screen on line " +
                               std::to_string(screens_[j].line()));
    screen.widthPx = s.integer("width_px", 1, maxPx);
    screen.heightPx = s.integer("height_px", 1, maxPx);
    screen.widthMm = s.numberAbove("width_mm", 0.0, maxMm);
    screen.heightMm = s.numberAbove("height_mm", 0.0, maxMm);
    screen.lowerLeftMm = {s.number("x_mm", -maxMm, maxMm), s.number("y_mm", -maxMm, maxMm)};
    screen.eye = Eye(s.choice("eye", {"centre", "left", "right"}, 0));
    if (s.has("stereo")) {
        forbid(s, "eye", "cannot be combined with stereo: a side-by-side screen shows both eyes");
        s.choice("stereo", {"side-by-side"}, 0);
        if (screen.widthPx % 2 != 0)
            s.fail("stereo", "a side-by-side screen needs an even width_px (got " + std::to_string(screen.widthPx) + ")");
        screen.eye = Eye::sideBySide;
    }
    return screen;
}

// A screen may not overlap an earlier one by more than 1e-6 mm each way, except that a left-eye and
// a right-eye screen may share the wall area (passive stereo).
void WallFile::checkOverlaps(const Screen& screen, const TableReader& s, const std::vector<Screen>& earlier) const
{
    for (std::size_t j = 0; j < earlier.size(); ++j) {
        const Screen& other = earlier[j];
        const bool otherEye = (screen.eye == Eye::left && other.eye == Eye::right) ||
                              (screen.eye == Eye::right && other.eye == Eye::left);
        if (otherEye)
            continue;
        const double overlapX = std::min(screen.lowerRight().x, other.lowerRight().x) -
                                std::max(screen.lowerLeftMm.x, other.lowerLeftMm.x);
        const double overlapY = std::min(screen.upperLeft().y, other.upperLeft().y) -
                                std::max(screen.lowerLeftMm.y, other.lowerLeftMm.y);
        if (overlapX > 1e-6 && overlapY > 1e-6)
            throw common::inputError(path_, s.line(),
                             "screen '" + screen.name + "' overlaps screen '" + other.name + "' (line " +
                                 std::to_string(screens_[j].line()) + ") by " + show(overlapX) + " x " + show(overlapY) + " mm");
    }
}

// Ranks given in every [[screen]] (then 0..N-1 without gaps), or in none: then screens_per_rank
// consecutive screens per rank, in file order.
void WallFile::numberRanks(std::vector<Screen>& screens, bool anyRank, std::optional<std::size_t> firstWithoutRank) const
{
    if (anyRank) {
        if (firstWithoutRank)
            throw common::inputError(path_, screens_[*firstWithoutRank].line(),
                             "screen '" + screens[*firstWithoutRank].name +
                                 "' has no rank while other screens do: give every screen a rank or none");
        forbid(ranks_, "screens_per_rank", "cannot be combined with a rank in each [[screen]]");
        std::vector<int> ranks;
        for (const Screen& screen : screens)
            ranks.push_back(screen.rank);
        if (const auto gap = rankGap(ranks))
            screens_[gap->first].fail("rank", gapProblem(gap->second, ranks[gap->first]));
    } else {
        const int perRank = ranks_.integer("screens_per_rank", 1, maxRank, 1);
        for (std::size_t i = 0; i < screens.size(); ++i)
            screens[i].rank = int(i) / perRank;
    }
}

// The projection (flat or dome master) and the interocular distance of a stereo wall.
void WallFile::readProjection(Wall& wall) const
{
    const TableReader eye = top_.optionalTable("eye");
    wall.interocularMm = eye.number("interocular_mm", 0.0, maxInterocularMm, 0.0);
    const bool stereo = std::any_of(wall.screens.begin(), wall.screens.end(),
                                    [](const Screen& s) { return s.eye != Eye::centre; });
    if (stereo && !eye.has("interocular_mm"))
        eye.fail("interocular_mm", "missing: screens show a left or right eye");

    const TableReader projection = top_.optionalTable("projection");
    projection.rejectKeysOutside(projectionKeys);
    const bool dome = projection.choice("kind", {"flat", "dome"}, 0) == 1;
    if (!dome) {
        forbid(projection, "field_of_view_deg", "applies only to projection.kind = \"dome\"");
        forbid(projection, "tilt_deg", "applies only to projection.kind = \"dome\"");
        return;
    }
    if (stereo || eye.has("interocular_mm"))
        projection.fail("kind", "a dome master has one eye: remove eye.interocular_mm and the screens' eye keys");
    wall.projection = Projection::dome;
    wall.dome.fieldOfViewDeg = projection.numberAbove("field_of_view_deg", 0.0, 360.0, 180.0);
    wall.dome.tiltDeg = projection.number("tilt_deg", -90.0, 90.0, 0.0);
}

void WallFile::checkRankCount(const Wall& wall) const
{
    if (!ranks_.has("count"))
        return;
    const int n = ranks_.integer("count", 1, maxRank + 1);
    const std::string used = "but the screens use ranks 0.." + std::to_string(wall.rankCount - 1);
    if (n > wall.rankCount)
        ranks_.fail("count", std::to_string(n) + " " + used + ": rank " + std::to_string(wall.rankCount) + " owns no screen");
    if (n < wall.rankCount)
        ranks_.fail("count", std::to_string(n) + " " + used);
}

void WallFile::placeWindows(Wall& wall) const
{
    const bool fullscreen = windows_.choice("mode", {"windowed", "fullscreen"}, 0) == 1;
    if (!fullscreen) {
        forbid(windows_, "monitors", "applies only to windows.mode = \"fullscreen\"");
        const glm::ivec2 origin{windows_.integer("origin_x_px", -maxPx, maxPx, 0),
                                windows_.integer("origin_y_px", -maxPx, maxPx, 0)};
        placeWindowsOnCanvas(wall, origin, windows_.numberAbove("scale", 0.0, maxWindowScale, 1.0));
        for (std::size_t i = 0; i < screens_.size(); ++i) {
            const TableReader& s = screens_[i];
            WindowPlacement& window = wall.screens[i].window;
            forbid(s, "monitor", "applies only to windows.mode = \"fullscreen\"");
            window.x = s.integer("window_x_px", -maxPx, maxPx, window.x);
            window.y = s.integer("window_y_px", -maxPx, maxPx, window.y);
        }
        return;
    }
    for (const char* key : {"origin_x_px", "origin_y_px", "scale"})
        forbid(windows_, key, "applies only to windows.mode = \"windowed\"");
    std::vector<int> monitors(wall.screens.size());
    // Default: a rank's k-th screen goes to its k-th monitor.
    for (int rank = 0; rank < wall.rankCount; ++rank) {
        const std::vector<int> owned = wall.screensOfRank(rank);
        for (std::size_t k = 0; k < owned.size(); ++k)
            monitors[owned[k]] = int(k);
    }
    if (windows_.has("monitors")) {
        if (!screens_.empty())
            windows_.fail("monitors", "applies only to a [grid]; give each [[screen]] a monitor");
        monitors = windows_.integers("monitors", 0, maxMonitor);
        if (monitors.size() != wall.screens.size())
            windows_.fail("monitors", "must list " + std::to_string(wall.screens.size()) +
                                          " monitors, one per screen row-major (got " + std::to_string(monitors.size()) + ")");
    }
    for (std::size_t i = 0; i < wall.screens.size(); ++i) {
        Screen& screen = wall.screens[i];
        screen.window = WindowPlacement{};
        screen.window.fullscreen = true;
        screen.window.monitor = monitors[i];
        if (i < screens_.size()) {
            const TableReader& s = screens_[i];
            forbid(s, "window_x_px", "applies only to windows.mode = \"windowed\"");
            forbid(s, "window_y_px", "applies only to windows.mode = \"windowed\"");
            screen.window.monitor = s.integer("monitor", 0, maxMonitor, monitors[i]);
        }
    }
}

} // namespace

Wall loadWall(const std::string& path)
{
    if (std::filesystem::exists(path) && !std::filesystem::is_regular_file(path))
        throw common::inputError(path, 0, "not a regular file (a wall file is a TOML text file)");
    if (!std::filesystem::is_regular_file(path) || !std::ifstream(path))
        throw common::inputError(path, 0, "cannot open the wall file");
    if (std::filesystem::path(path).extension() == ".ini")
        throw common::inputError(path, 0, convertHint);
    if (const int line = oldIniLine(path))
        throw common::inputError(path, line, "old INI syntax: " + convertHint);
    const config::TomlFile root = config::parseTomlFile(path);
    return WallFile(root, path).load();
}

} // namespace aurorawall::wall
