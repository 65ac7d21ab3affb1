#include "wall/wall_file.h"

#include "common/input_error.h"

#include <boost/program_options/options_description.hpp>
#include <boost/program_options/parsers.hpp>

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <stdexcept>

namespace aurorawall::wall {
namespace {

namespace po = boost::program_options;

// Bounds that catch unit mix-ups (metres for millimetres, a canvas for a screen) and garbage.
constexpr double maxMm = 1e6;
constexpr int maxPx = 65536;
constexpr int maxGridSide = 1024;
constexpr int maxRank = 65535;
constexpr int maxMonitor = 63;
constexpr double maxWindowScale = 16.0;

// The keys each section accepts; [screen.NAME] sections share one list.
const std::map<std::string, std::set<std::string>> knownKeys = {
    {"grid", {"columns", "rows", "width_px", "height_px", "width_mm", "height_mm", "bezel_horizontal_mm",
              "bezel_vertical_mm"}},
    {"screen", {"width_px", "height_px", "width_mm", "height_mm", "x_mm", "y_mm", "rank", "monitor",
                "window_x_px", "window_y_px"}},
    {"eye", {"x_mm", "y_mm", "z_mm"}},
    {"ranks", {"screens_per_rank", "stacking", "per_screen", "count"}},
    {"windows", {"mode", "origin_x_px", "origin_y_px", "scale", "monitors"}},
};

std::string trim(const std::string& s)
{
    const auto first = s.find_first_not_of(" \t\r");
    if (first == std::string::npos)
        return {};
    return s.substr(first, s.find_last_not_of(" \t\r") - first + 1);
}

std::string show(double x)
{
    std::ostringstream out;
    out << x;
    return out.str();
}

bool isScreenSection(const std::string& section) { return section.rfind("screen.", 0) == 0 && section.size() > 7; }

struct Entry {
    std::string section, key, value;
    int line = 0;
};

struct SectionHeader {
    std::string name;
    int line = 0;
};

// One wall file: the scan that knows where each key is (Boost.Program_options reports no lines),
// typed, range-checked access to the values Boost parsed, and the assembly of the wall.
class WallFile {
public:
    explicit WallFile(std::string path) : path_(std::move(path)) {}
    Wall load();

private:
    [[noreturn]] void fail(int line, const std::string& message) const { throw inputError(path_, line, message); }

    void scan(std::istream& in, std::ostringstream& text);
    void parseWithBoost(const std::string& text);
    void checkNames() const;

    const SectionHeader* section(const std::string& name) const;
    int sectionLine(const std::string& name) const { return section(name) ? section(name)->line : 0; }
    const Entry* find(const std::string& sectionName, const std::string& key) const;
    const Entry& require(const std::string& sectionName, const std::string& key, const std::string& meaning) const;

    double realOf(const Entry& e, double lo, double hi, bool loOpen, const std::string& meaning = {}) const;
    int integerOf(const Entry& e, const std::string& text, long long lo, long long hi) const;
    double real(const std::string& s, const std::string& k, double lo, double hi, bool loOpen, const std::string& meaning) const
    {
        return realOf(require(s, k, meaning), lo, hi, loOpen, meaning);
    }
    double real(const std::string& s, const std::string& k, double lo, double hi, bool loOpen, double fallback) const
    {
        const Entry* e = find(s, k);
        return e ? realOf(*e, lo, hi, loOpen) : fallback;
    }
    int integer(const std::string& s, const std::string& k, int lo, int hi, const std::string& meaning) const
    {
        const Entry& e = require(s, k, meaning);
        return integerOf(e, e.value, lo, hi);
    }
    std::optional<int> optionalInteger(const std::string& s, const std::string& k, int lo, int hi) const
    {
        const Entry* e = find(s, k);
        return e ? std::optional<int>(integerOf(*e, e->value, lo, hi)) : std::nullopt;
    }
    std::vector<int> integerList(const Entry& e, int lo, int hi, std::size_t count) const;
    std::string word(const std::string& s, const std::string& k, const std::set<std::string>& choices,
                     const std::string& fallback) const;
    void forbid(const std::string& s, const std::string& k, const std::string& reason) const
    {
        if (const Entry* e = find(s, k))
            fail(e->line, s + "." + k + " " + reason);
    }

    Wall gridWall();
    Wall screenListWall();
    void checkRanks(const std::vector<int>& ranks, const std::vector<int>& lines) const;
    void checkRankCount(const Wall& wall) const;
    void placeWindows(Wall& wall) const;

    std::string path_;
    std::vector<SectionHeader> sections_;  // in file order
    std::map<std::string, Entry> entries_; // by "section.key", Boost's naming
};

Wall WallFile::load()
{
    std::ifstream in(path_);
    if (!in)
        fail(0, "cannot open the wall file");
    std::ostringstream text;
    scan(in, text);
    parseWithBoost(text.str());
    checkNames();

    const bool hasGrid = section("grid") != nullptr;
    for (const SectionHeader& s : sections_)
        if (hasGrid && isScreenSection(s.name))
            fail(s.line, "[" + s.name + "] cannot be combined with [grid]: describe the wall as a grid or as a list of screens");
    Wall wall = hasGrid ? gridWall() : screenListWall();
    checkRankCount(wall);
    placeWindows(wall);
    return wall;
}

// Mirrors Boost's config-file grammar: '#' starts a comment, "[section]" prefixes the keys that
// follow with "section.", every other non-blank line is "key = value".
void WallFile::scan(std::istream& in, std::ostringstream& text)
{
    std::string raw, current;
    int line = 0;
    while (std::getline(in, raw)) {
        ++line;
        text << raw << '\n';
        const std::string s = trim(raw.substr(0, raw.find('#')));
        if (s.empty())
            continue;
        if (s.front() == '[') {
            if (s.back() != ']' || s.size() < 3)
                fail(line, "syntax error: expected '[section]' (got '" + s + "')");
            current = s.substr(1, s.size() - 2);
            if (const SectionHeader* previous = section(current))
                fail(line, "duplicate section [" + current + "] (first on line " + std::to_string(previous->line) + ")");
            sections_.push_back({current, line});
            continue;
        }
        const auto equals = s.find('=');
        if (equals == std::string::npos)
            fail(line, "syntax error: expected 'key = value' or '[section]' (got '" + s + "')");
        const std::string key = trim(s.substr(0, equals));
        if (key.empty())
            fail(line, "syntax error: no key before '='");
        const std::string name = current.empty() ? key : current + "." + key;
        if (const auto it = entries_.find(name); it != entries_.end())
            fail(line, "duplicate key " + name + " (first on line " + std::to_string(it->second.line) + ")");
        entries_[name] = {current, key, trim(s.substr(equals + 1)), line};
    }
}

void WallFile::parseWithBoost(const std::string& text)
{
    std::istringstream in(text);
    try {
        const po::parsed_options parsed = po::parse_config_file(in, po::options_description(), true);
        for (const po::option& option : parsed.options) {
            const auto it = entries_.find(option.string_key);
            if (it == entries_.end())
                fail(0, "unexpected key " + option.string_key);
            it->second.value = option.value.empty() ? std::string() : option.value.front();
        }
    } catch (const po::error& e) {
        fail(0, std::string("syntax error: ") + e.what());
    }
}

void WallFile::checkNames() const
{
    for (const SectionHeader& s : sections_)
        if (!knownKeys.count(s.name) && !isScreenSection(s.name))
            fail(s.line, "unknown section [" + s.name + "]; expected [grid], [screen.NAME], [eye], [ranks] or [windows]");
    for (const auto& [name, e] : entries_) {
        if (e.section.empty())
            fail(e.line, "key '" + e.key + "' is outside any section");
        const std::set<std::string>& keys = knownKeys.at(isScreenSection(e.section) ? "screen" : e.section);
        if (!keys.count(e.key)) {
            std::string known;
            for (const std::string& k : keys)
                known += (known.empty() ? "" : ", ") + k;
            fail(e.line, "unknown key '" + e.key + "' in [" + e.section + "]; known keys: " + known);
        }
    }
}

const SectionHeader* WallFile::section(const std::string& name) const
{
    for (const SectionHeader& s : sections_)
        if (s.name == name)
            return &s;
    return nullptr;
}

const Entry* WallFile::find(const std::string& sectionName, const std::string& key) const
{
    const auto it = entries_.find(sectionName + "." + key);
    return it == entries_.end() ? nullptr : &it->second;
}

const Entry& WallFile::require(const std::string& sectionName, const std::string& key, const std::string& meaning) const
{
    if (const Entry* e = find(sectionName, key))
        return *e;
    fail(sectionLine(sectionName), "[" + sectionName + "] needs " + key + " (" + meaning + ")");
}

double WallFile::realOf(const Entry& e, double lo, double hi, bool loOpen, const std::string& meaning) const
{
    const std::string name = e.section + "." + e.key;
    const char* begin = e.value.c_str();
    char* end = nullptr;
    errno = 0;
    const double x = std::strtod(begin, &end);
    if (e.value.empty() || *end != '\0')
        fail(e.line, name + " must be a number (got '" + e.value + "')");
    if (!std::isfinite(x) || errno == ERANGE)
        fail(e.line, name + " must be a finite number (got '" + e.value + "')");
    if (x > hi || x < lo || (loOpen && x == lo))
        fail(e.line, name + " must be " + (loOpen ? "> " : ">= ") + show(lo) + " and <= " + show(hi) + " (got " + e.value +
                         ")" + (meaning.empty() ? "" : ": " + meaning));
    return x;
}

int WallFile::integerOf(const Entry& e, const std::string& text, long long lo, long long hi) const
{
    const std::string name = e.section + "." + e.key;
    char* end = nullptr;
    errno = 0;
    const long long x = std::strtoll(text.c_str(), &end, 10);
    if (text.empty() || *end != '\0')
        fail(e.line, name + " must be an integer (got '" + text + "')");
    if (errno == ERANGE || x < lo || x > hi)
        fail(e.line, name + " must be >= " + std::to_string(lo) + " and <= " + std::to_string(hi) + " (got " + text + ")");
    return int(x);
}

std::vector<int> WallFile::integerList(const Entry& e, int lo, int hi, std::size_t count) const
{
    std::istringstream in(e.value);
    std::vector<int> values;
    for (std::string item; in >> item;)
        values.push_back(integerOf(e, item, lo, hi));
    if (values.size() != count)
        fail(e.line, e.section + "." + e.key + " must list " + std::to_string(count) + " integers, one per screen row-major (got " +
                         std::to_string(values.size()) + ")");
    return values;
}

std::string WallFile::word(const std::string& s, const std::string& k, const std::set<std::string>& choices,
                           const std::string& fallback) const
{
    const Entry* e = find(s, k);
    if (!e)
        return fallback;
    if (!choices.count(e->value)) {
        std::string list;
        for (const std::string& c : choices)
            list += (list.empty() ? "" : " or ") + c;
        fail(e->line, s + "." + k + " must be " + list + " (got '" + e->value + "')");
    }
    return e->value;
}

Wall WallFile::gridWall()
{
    GridSpec grid;
    grid.columns = integer("grid", "columns", 1, maxGridSide, "the number of screens across");
    grid.rows = integer("grid", "rows", 1, maxGridSide, "the number of screens down");
    grid.screenPx = {integer("grid", "width_px", 1, maxPx, "one screen's width in pixels"),
                     integer("grid", "height_px", 1, maxPx, "one screen's height in pixels")};
    grid.screenMm = {real("grid", "width_mm", 0.0, maxMm, true, "one screen's active width in millimetres"),
                     real("grid", "height_mm", 0.0, maxMm, true, "one screen's active height in millimetres")};
    grid.bezelMm = {real("grid", "bezel_horizontal_mm", 0.0, maxMm, false, 0.0),
                    real("grid", "bezel_vertical_mm", 0.0, maxMm, false, 0.0)};
    grid.eyeFromCentreMm = {real("eye", "x_mm", -maxMm, maxMm, false, 0.0), real("eye", "y_mm", -maxMm, maxMm, false, 0.0),
                            real("eye", "z_mm", 0.0, maxMm, true, "the eye's distance in front of the wall")};

    const Entry* perScreen = find("ranks", "per_screen");
    if (perScreen) {
        forbid("ranks", "screens_per_rank", "cannot be combined with ranks.per_screen");
        forbid("ranks", "stacking", "cannot be combined with ranks.per_screen");
    } else {
        grid.stacking = word("ranks", "stacking", {"horizontal", "vertical"}, "horizontal") == "vertical" ? Stacking::vertical
                                                                                                         : Stacking::horizontal;
        grid.screensPerRank = optionalInteger("ranks", "screens_per_rank", 1, maxRank).value_or(1);
        const bool vertical = grid.stacking == Stacking::vertical;
        const int stacked = vertical ? grid.rows : grid.columns;
        if (stacked % grid.screensPerRank != 0)
            fail(find("ranks", "screens_per_rank")->line,
                 "ranks.screens_per_rank = " + std::to_string(grid.screensPerRank) + " must divide grid." +
                     (vertical ? "rows = " : "columns = ") + std::to_string(stacked) + " (stacking = " +
                     (vertical ? "vertical" : "horizontal") + ")");
    }
    Wall wall;
    try {
        wall = makeGridWall(grid);
        if (perScreen) {
            const std::vector<int> ranks = integerList(*perScreen, 0, maxRank, wall.screens.size());
            checkRanks(ranks, std::vector<int>(ranks.size(), perScreen->line));
            for (std::size_t i = 0; i < ranks.size(); ++i)
                wall.screens[i].rank = ranks[i];
            wall = assembleWall(std::move(wall.screens), wall.eyeMm);
        }
    } catch (const std::invalid_argument& e) {
        fail(0, e.what());
    }
    wall.sourceFile = path_;
    return wall;
}

Wall WallFile::screenListWall()
{
    forbid("ranks", "stacking", "applies only to a [grid]");
    forbid("ranks", "per_screen", "applies only to a [grid]; give each [screen.NAME] a rank");
    std::vector<Screen> screens;
    std::vector<int> sectionLines, rankLines;
    const SectionHeader* firstWithoutRank = nullptr;
    for (const SectionHeader& header : sections_) {
        if (!isScreenSection(header.name))
            continue;
        const std::string& s = header.name;
        Screen screen;
        screen.name = s.substr(7);
        screen.widthPx = integer(s, "width_px", 1, maxPx, "width in pixels");
        screen.heightPx = integer(s, "height_px", 1, maxPx, "height in pixels");
        screen.widthMm = real(s, "width_mm", 0.0, maxMm, true, "active width in millimetres");
        screen.heightMm = real(s, "height_mm", 0.0, maxMm, true, "active height in millimetres");
        screen.lowerLeftMm = {real(s, "x_mm", -maxMm, maxMm, false, "the active area's left edge in millimetres"),
                              real(s, "y_mm", -maxMm, maxMm, false, "the active area's bottom edge in millimetres")};
        for (std::size_t j = 0; j < screens.size(); ++j) {
            const Screen& other = screens[j];
            const double overlapX = std::min(screen.lowerRight().x, other.lowerRight().x) -
                                    std::max(screen.lowerLeftMm.x, other.lowerLeftMm.x);
            const double overlapY = std::min(screen.upperLeft().y, other.upperLeft().y) -
                                    std::max(screen.lowerLeftMm.y, other.lowerLeftMm.y);
            if (overlapX > 1e-6 && overlapY > 1e-6)
                fail(header.line, "screen '" + screen.name + "' overlaps screen '" + other.name + "' (line " +
                                      std::to_string(sectionLines[j]) + ") by " + show(overlapX) + " x " + show(overlapY) + " mm");
        }
        if (const Entry* rank = find(s, "rank")) {
            screen.rank = integerOf(*rank, rank->value, 0, maxRank);
            rankLines.push_back(rank->line);
        } else if (!firstWithoutRank) {
            firstWithoutRank = &header;
        }
        screens.push_back(screen);
        sectionLines.push_back(header.line);
    }
    if (screens.empty())
        fail(0, "no screens: the file needs a [grid] section or [screen.NAME] sections");

    if (!rankLines.empty()) {
        if (firstWithoutRank)
            fail(firstWithoutRank->line, "[" + firstWithoutRank->name + "] has no rank while other screens do: give every screen a rank or none");
        forbid("ranks", "screens_per_rank", "cannot be combined with a rank in each [screen.NAME]");
        std::vector<int> ranks;
        for (const Screen& screen : screens)
            ranks.push_back(screen.rank);
        checkRanks(ranks, rankLines);
    } else {
        const int perRank = optionalInteger("ranks", "screens_per_rank", 1, maxRank).value_or(1);
        for (std::size_t i = 0; i < screens.size(); ++i)
            screens[i].rank = int(i) / perRank;
    }

    // The eye is given relative to the centre of the screens' bounding box.
    glm::dvec2 lo = screens.front().lowerLeftMm, hi = lo;
    for (const Screen& screen : screens) {
        lo = glm::min(lo, screen.lowerLeftMm);
        hi = glm::max(hi, glm::dvec2(screen.upperRight()));
    }
    const glm::dvec3 eye = glm::dvec3((lo + hi) / 2.0, 0.0) +
                           glm::dvec3(real("eye", "x_mm", -maxMm, maxMm, false, 0.0), real("eye", "y_mm", -maxMm, maxMm, false, 0.0),
                                      real("eye", "z_mm", 0.0, maxMm, true, "the eye's distance in front of the wall"));
    try {
        return assembleWall(std::move(screens), eye, path_);
    } catch (const std::invalid_argument& e) {
        fail(0, e.what());
    }
}

// Explicit ranks must be 0..N-1 without gaps; a gap is reported at the first rank above it.
void WallFile::checkRanks(const std::vector<int>& ranks, const std::vector<int>& lines) const
{
    const std::set<int> used(ranks.begin(), ranks.end());
    for (int r = 0; r < *used.rbegin(); ++r) {
        if (used.count(r))
            continue;
        const int above = *used.upper_bound(r);
        for (std::size_t i = 0; i < ranks.size(); ++i)
            if (ranks[i] == above)
                fail(lines[i], "ranks must be numbered 0..N-1 without gaps: rank " + std::to_string(r) +
                                   " owns no screen, but rank " + std::to_string(above) + " does");
    }
}

void WallFile::checkRankCount(const Wall& wall) const
{
    const Entry* count = find("ranks", "count");
    if (!count)
        return;
    const int n = integerOf(*count, count->value, 1, maxRank + 1);
    if (n > wall.rankCount)
        fail(count->line, "ranks.count = " + std::to_string(n) + " but the screens use ranks 0.." +
                              std::to_string(wall.rankCount - 1) + ": rank " + std::to_string(wall.rankCount) + " owns no screen");
    if (n < wall.rankCount)
        fail(count->line, "ranks.count = " + std::to_string(n) + " but the screens use ranks 0.." + std::to_string(wall.rankCount - 1));
}

void WallFile::placeWindows(Wall& wall) const
{
    const bool fullscreen = word("windows", "mode", {"windowed", "fullscreen"}, "windowed") == "fullscreen";
    if (!fullscreen) {
        forbid("windows", "monitors", "applies only to windows.mode = fullscreen");
        const glm::ivec2 origin{optionalInteger("windows", "origin_x_px", -maxPx, maxPx).value_or(0),
                                optionalInteger("windows", "origin_y_px", -maxPx, maxPx).value_or(0)};
        placeWindowsOnCanvas(wall, origin, real("windows", "scale", 0.0, maxWindowScale, true, 1.0));
        for (Screen& screen : wall.screens) {
            const std::string s = "screen." + screen.name;
            forbid(s, "monitor", "applies only to windows.mode = fullscreen");
            screen.window.x = optionalInteger(s, "window_x_px", -maxPx, maxPx).value_or(screen.window.x);
            screen.window.y = optionalInteger(s, "window_y_px", -maxPx, maxPx).value_or(screen.window.y);
        }
        return;
    }
    for (const char* key : {"origin_x_px", "origin_y_px", "scale"})
        forbid("windows", key, "applies only to windows.mode = windowed");
    std::vector<int> monitors(wall.screens.size());
    // Default: a rank's k-th screen goes to its k-th monitor.
    for (int rank = 0; rank < wall.rankCount; ++rank) {
        const std::vector<int> owned = wall.screensOfRank(rank);
        for (std::size_t k = 0; k < owned.size(); ++k)
            monitors[owned[k]] = int(k);
    }
    if (const Entry* list = find("windows", "monitors")) {
        if (!section("grid"))
            fail(list->line, "windows.monitors applies only to a [grid]; give each [screen.NAME] a monitor");
        monitors = integerList(*list, 0, maxMonitor, wall.screens.size());
    }
    for (std::size_t i = 0; i < wall.screens.size(); ++i) {
        Screen& screen = wall.screens[i];
        const std::string s = "screen." + screen.name;
        forbid(s, "window_x_px", "applies only to windows.mode = windowed");
        forbid(s, "window_y_px", "applies only to windows.mode = windowed");
        screen.window = WindowPlacement{};
        screen.window.fullscreen = true;
        screen.window.monitor = optionalInteger(s, "monitor", 0, maxMonitor).value_or(monitors[i]);
    }
}

} // namespace

Wall loadWall(const std::string& path) { return WallFile(path).load(); }

} // namespace aurorawall::wall
