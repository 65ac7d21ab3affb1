#include "app/cost_map.h"

#include "cli/exit_status.h"
#include "io/png.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <map>
#include <stdexcept>

namespace aurorawall::app {

namespace {

// Entries 0, 32, 64, ..., 224 and 255 of matplotlib's 256-entry viridis table (_cm_listed.py,
// S. van der Walt and N. Smith 2015, CC0), sRGB in [0, 1].
constexpr int kViridisNodes = 9;
constexpr double kViridisIndex[kViridisNodes] = {0, 32, 64, 96, 128, 160, 192, 224, 255};
constexpr double kViridis[kViridisNodes][3] = {
    {0.267004, 0.004874, 0.329415}, {0.278826, 0.175490, 0.483397}, {0.229739, 0.322361, 0.545706},
    {0.172719, 0.448791, 0.557885}, {0.127568, 0.566949, 0.550556}, {0.157851, 0.683765, 0.501686},
    {0.369214, 0.788888, 0.382914}, {0.678489, 0.863742, 0.189503}, {0.993248, 0.906157, 0.143936}};

// A 5x7 bitmap font for the scale bar's labels: each row's 5 bits, the leftmost pixel the highest.
using Glyph = std::array<std::uint8_t, 7>;
const std::map<char, Glyph>& font()
{
    static const std::map<char, Glyph> glyphs = {
        {'0', {0x0E, 0x11, 0x13, 0x15, 0x19, 0x11, 0x0E}}, {'1', {0x04, 0x0C, 0x04, 0x04, 0x04, 0x04, 0x0E}},
        {'2', {0x0E, 0x11, 0x01, 0x02, 0x04, 0x08, 0x1F}}, {'3', {0x1F, 0x02, 0x04, 0x02, 0x01, 0x11, 0x0E}},
        {'4', {0x02, 0x06, 0x0A, 0x12, 0x1F, 0x02, 0x02}}, {'5', {0x1F, 0x10, 0x1E, 0x01, 0x01, 0x11, 0x0E}},
        {'6', {0x06, 0x08, 0x10, 0x1E, 0x11, 0x11, 0x0E}}, {'7', {0x1F, 0x01, 0x02, 0x04, 0x08, 0x08, 0x08}},
        {'8', {0x0E, 0x11, 0x11, 0x0E, 0x11, 0x11, 0x0E}}, {'9', {0x0E, 0x11, 0x11, 0x0F, 0x01, 0x02, 0x0C}},
        {'.', {0x00, 0x00, 0x00, 0x00, 0x00, 0x0C, 0x0C}}, {' ', {0, 0, 0, 0, 0, 0, 0}},
        {'a', {0x00, 0x00, 0x0E, 0x01, 0x0F, 0x11, 0x0F}}, {'e', {0x00, 0x00, 0x0E, 0x11, 0x1F, 0x10, 0x0E}},
        {'i', {0x04, 0x00, 0x0C, 0x04, 0x04, 0x04, 0x0E}}, {'l', {0x0C, 0x04, 0x04, 0x04, 0x04, 0x04, 0x0E}},
        {'m', {0x00, 0x00, 0x1A, 0x15, 0x15, 0x11, 0x11}}, {'n', {0x00, 0x00, 0x16, 0x19, 0x11, 0x11, 0x11}},
        {'p', {0x00, 0x00, 0x1E, 0x11, 0x1E, 0x10, 0x10}}, {'r', {0x00, 0x00, 0x16, 0x19, 0x10, 0x10, 0x10}},
        {'s', {0x00, 0x00, 0x0E, 0x10, 0x0E, 0x01, 0x1E}}, {'t', {0x08, 0x08, 0x1C, 0x08, 0x08, 0x09, 0x06}},
        {'x', {0x00, 0x00, 0x11, 0x0A, 0x04, 0x0A, 0x11}}};
    return glyphs;
}

const char* const kCaption = "ns per pixel estimate";

// Pixels of the bar's font and spacing per bitmap pixel: 1 up to 800 pixels wide, then wider.
int barScale(int width) { return std::max(1, width / 800); }

void setPixel(Picture& p, int x, int y, Rgb8 c)
{
    if (x >= 0 && x < p.width && y >= 0 && y < p.height)
        std::memcpy(&p.rgb[3 * (std::size_t(y) * p.width + x)], c.data(), 3);
}

int textWidth(const std::string& text, int s) { return text.empty() ? 0 : int(text.size()) * 6 * s - s; }

// White text whose top-left corner is (x, y), kept inside the picture's width.
void drawText(Picture& p, const std::string& text, int x, int y, int s)
{
    x = std::clamp(x, 0, std::max(0, p.width - textWidth(text, s)));
    for (char ch : text) {
        const Glyph& g = font().at(ch);
        for (int row = 0; row < 7; ++row)
            for (int col = 0; col < 5; ++col)
                if (g[row] & (0x10 >> col))
                    for (int dy = 0; dy < s; ++dy)
                        for (int dx = 0; dx < s; ++dx)
                            setPixel(p, x + col * s + dx, y + row * s + dy, {255, 255, 255});
        x += 6 * s;
    }
}

// Three significant figures without an exponent: 0.412, 41.2, 4120.
std::string tickLabel(double ns)
{
    char text[32];
    std::snprintf(text, sizeof text, ns >= 100 ? "%.0f" : ns >= 10 ? "%.1f" : "%.2f", ns);
    return text;
}

// The bar's rows, from its top: a margin, the colour strip, a tick, a gap, the tick labels, a gap,
// the caption, a margin (in units of barScale).
constexpr int kMargin = 6, kStrip = 12, kTick = 3, kGap = 3, kText = 7;

} // namespace

Rgb8 viridis(double t)
{
    const double index = 255.0 * std::clamp(std::isnan(t) ? 0.0 : t, 0.0, 1.0);
    int k = 0;
    while (k < kViridisNodes - 2 && index > kViridisIndex[k + 1])
        ++k;
    const double f = (index - kViridisIndex[k]) / (kViridisIndex[k + 1] - kViridisIndex[k]);
    Rgb8 c;
    for (int i = 0; i < 3; ++i)
        c[i] = std::uint8_t(std::lround(255.0 * ((1.0 - f) * kViridis[k][i] + f * kViridis[k + 1][i])));
    return c;
}

double CostScale::position(double cost) const
{
    if (!(high > low) || !(cost > 0))
        return 0.0;
    return std::clamp(std::log(cost / low) / std::log(high / low), 0.0, 1.0);
}

Rgb8 Picture::at(int x, int y) const
{
    const std::uint8_t* p = &rgb[3 * (std::size_t(y) * width + x)];
    return {p[0], p[1], p[2]};
}

int scaleBarHeight(int width) { return barScale(width) * (2 * kMargin + kStrip + kTick + 2 * kGap + 2 * kText); }

Picture costMapPicture(int width, int height, const std::vector<double>& costNs)
{
    if (width <= 0 || height <= 0 || costNs.size() != std::size_t(width) * height)
        throw std::invalid_argument("cost map: " + std::to_string(costNs.size()) + " costs for " +
                                    std::to_string(width) + "x" + std::to_string(height) + " pixels");
    CostScale scale{0.0, 0.0};
    for (double c : costNs)
        if (c > 0) {
            scale.low = scale.low > 0 ? std::min(scale.low, c) : c;
            scale.high = std::max(scale.high, c);
        }
    Picture p;
    p.width = width;
    p.height = height + scaleBarHeight(width);
    p.rgb.assign(3 * std::size_t(p.width) * p.height, 0);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const double c = costNs[std::size_t(y) * width + x];
            if (c > 0)
                setPixel(p, x, y, viridis(scale.position(c)));
        }

    const int s = barScale(width);
    const int x0 = kMargin * s, x1 = std::max(x0 + 1, width - 1 - kMargin * s);
    const int stripTop = height + kMargin * s, stripBottom = stripTop + kStrip * s;
    for (int x = x0; x <= x1; ++x)
        for (int y = stripTop; y < stripBottom; ++y)
            setPixel(p, x, y, viridis(double(x - x0) / (x1 - x0)));
    // Ticks evenly spaced in log(cost), labelled with their cost.
    const int ticks = scale.high > scale.low ? (width >= 320 ? 5 : 2) : 1;
    const int labelTop = stripBottom + (kTick + kGap) * s;
    for (int k = 0; k < ticks; ++k) {
        const double f = ticks > 1 ? double(k) / (ticks - 1) : 0.0;
        const int x = x0 + int(std::lround(f * (x1 - x0)));
        for (int y = stripBottom; y < stripBottom + kTick * s; ++y)
            for (int dx = 0; dx < s; ++dx)
                setPixel(p, x + dx, y, {255, 255, 255});
        const std::string label = tickLabel(scale.low * std::pow(scale.high / scale.low, f));
        drawText(p, label, x - textWidth(label, s) / 2, labelTop, s);
    }
    drawText(p, kCaption, x0, labelTop + (kText + kGap) * s, s);
    return p;
}

void writePicturePng(const std::string& path, const Picture& picture)
{
    io::writePngRgb8(path, picture.width, picture.height, picture.rgb);
}

int writeCostMap(WallSession& session, const cluster::MpiWorld& world, const cluster::FrameStats& stats)
{
    // Each screen travels as a header (rank, screen, width, height) and its work, rows top-down.
    std::vector<char> mine;
    int status = agreedStep(world, [&] {
        for (ScreenTarget& s : session.screens) {
            session.context->makeCurrent(s.window);
            const int w = s.target->width(), h = s.target->height();
            const std::vector<float> bottomUp = s.target->readbackWork(0, h);
            const int header[4] = {world.rank(), s.screen, w, h};
            const char* bytes = reinterpret_cast<const char*>(header);
            mine.insert(mine.end(), bytes, bytes + sizeof header);
            for (int y = h - 1; y >= 0; --y) {
                const char* row = reinterpret_cast<const char*>(&bottomUp[std::size_t(y) * w]);
                mine.insert(mine.end(), row, row + w * sizeof(float));
            }
        }
        session.context->makeCurrent(0);
    });
    if (status != cli::kSuccess)
        return status;
    std::vector<int> sizes;
    const std::vector<char> gathered = world.gatherBytes(mine, sizes);
    return agreedStep(world, [&] {
        if (!world.isMaster())
            return;
        if (stats.records().empty())
            throw std::runtime_error("--cost-map: no frame was rendered");
        const std::vector<cluster::RankReport>& reports = stats.records().back().ranks;
        const wall::Wall& wall = session.wall;
        const int width = wall.canvasSizePx.x, height = wall.canvasSizePx.y;
        std::vector<double> work(std::size_t(width) * height, 0.0);
        std::vector<int> owner(work.size(), -1);
        std::vector<double> rankWork(reports.size(), 0.0);
        for (std::size_t at = 0; at < gathered.size();) {
            int header[4];
            std::memcpy(header, gathered.data() + at, sizeof header);
            at += sizeof header;
            const auto [rank, screen, w, h] = header;
            const glm::ivec2 offset = wall.screens[screen].canvasOffsetPx;
            for (int y = 0; y < h; ++y)
                for (int x = 0; x < w; ++x, at += sizeof(float)) {
                    float value;
                    std::memcpy(&value, gathered.data() + at, sizeof value);
                    const std::size_t i = std::size_t(offset.y + y) * width + offset.x + x;
                    work[i] = value;
                    owner[i] = rank;
                    rankWork.at(rank) += value;
                }
        }
        std::vector<double> cost(work.size(), 0.0);
        for (std::size_t i = 0; i < work.size(); ++i)
            if (owner[i] >= 0 && rankWork[owner[i]] > 0)
                cost[i] = work[i] * reports[owner[i]].renderMs * 1e6 / rankWork[owner[i]];
        writePicturePng(session.options.costMapFile, costMapPicture(width, height, cost));
    });
}

} // namespace aurorawall::app
