// compare_walls: checks on the images `aurorawall render` writes, for the end-to-end tests.
//
//   compare_walls diff REF.exr OTHER.exr [--half-ulps N]
//       Same size; every channel of every pixel within N half-float ulps (default 0: identical).
//   compare_walls content IMAGE.exr WALL.toml [--min-max V] [--min-lit-screens K] [--lit-above L]
//       No non-finite or clamped (HALF_MAX) values, brightest channel >= V, and at least K screens
//       of the wall (their canvas rectangles) with at least 1% and at most 99% of their pixels
//       brighter than L (default 1e-4) in some channel: structure, not a flat fill.
//   compare_walls bezel WALL.toml REF.exr GATHERED.exr [--half-ulps N]
//       REF is the --single-screen render of the wall's whole canvas, GATHERED the wall's
//       --gather: screen pixels as in diff, bezel pixels (in no screen) exactly black in GATHERED
//       and, so that the check means something, not all black in REF.
//   compare_walls tiles WALL.toml REF.exr TILE_DIR [--half-ulps N]
//       TILE_DIR/tile-<screen>.exr equals REF cropped at the screen's canvas offset, for every screen.
//   compare_walls dome WALL.toml IMAGE.exr
//       WALL is a dome master: every pixel whose centre lies outside the image circle (the canvas's
//       inscribed circle of the canvas height) is exactly black, and the pixels inside it are not all black.
//
// Every command prints its measurements on one line ("max_abs=... max_rel=...") and exits 0 when
// the check holds, 1 when it does not, 2 on bad usage or unreadable files.
#include "io/exr.h"
#include "io/image.h"
#include "wall/tile_rays.h"
#include "wall/wall_file.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <limits>
#include <map>
#include <string>
#include <vector>

namespace {

using aurorawall::io::Image;

constexpr double kHalfMax = 65504.0;

// One unit in the last place of a half float near |v|: 2^(e - 10) for normal halves (2^-14 <= |v|),
// 2^-24 for subnormal ones. Half-float rounding of two floats that differ in their last bits
// moves them at most one such step apart.
double halfUlp(double v)
{
    v = std::abs(v);
    if (v < std::ldexp(1.0, -14))
        return std::ldexp(1.0, -24);
    int e = 0;
    std::frexp(v, &e); // v = m * 2^e, m in [0.5, 1)
    return std::ldexp(1.0, e - 1 - 10);
}

struct Difference {
    double maxAbs = 0, maxRel = 0, worstUlps = 0;
    long differingChannels = 0, failingChannels = 0, compared = 0;
    double referenceMax = 0;
    void add(double a, double b, double halfUlps)
    {
        ++compared;
        referenceMax = std::max(referenceMax, std::abs(a));
        const double d = std::abs(a - b);
        if (!std::isfinite(d)) {
            maxAbs = maxRel = worstUlps = std::numeric_limits<double>::infinity();
            ++differingChannels;
            ++failingChannels;
            return;
        }
        if (d == 0)
            return;
        ++differingChannels;
        const double scale = std::max(std::abs(a), std::abs(b));
        maxAbs = std::max(maxAbs, d);
        maxRel = std::max(maxRel, d / scale);
        const double ulps = d / halfUlp(scale);
        worstUlps = std::max(worstUlps, ulps);
        if (ulps > halfUlps)
            ++failingChannels;
    }
    void print(const char* what) const
    {
        std::printf("%s: max_abs=%.9g max_rel=%.9g worst_half_ulps=%.3g differing_channels=%ld failing_channels=%ld "
                    "of %ld, reference_max=%.6g\n",
                    what, maxAbs, maxRel, worstUlps, differingChannels, failingChannels, compared, referenceMax);
    }
};

[[noreturn]] void usage(const std::string& problem)
{
    std::fprintf(stderr, "compare_walls: %s\n(see the top of tests/app/compare_walls.cpp for the commands)\n",
                 problem.c_str());
    std::exit(2);
}

// Positional arguments and --name value options.
struct Args {
    std::vector<std::string> positional;
    std::map<std::string, double> options;
    double option(const std::string& name, double fallback) const
    {
        auto it = options.find(name);
        return it == options.end() ? fallback : it->second;
    }
};

Args parseArgs(int argc, char** argv, const std::vector<std::string>& knownOptions)
{
    Args a;
    for (int i = 2; i < argc; ++i) {
        const std::string s = argv[i];
        if (s.rfind("--", 0) == 0) {
            if (std::find(knownOptions.begin(), knownOptions.end(), s.substr(2)) == knownOptions.end())
                usage("unknown option " + s);
            if (i + 1 >= argc)
                usage(s + " needs a value");
            char* end = nullptr;
            const double v = std::strtod(argv[i + 1], &end);
            if (*end || !std::isfinite(v))
                usage(s + ": not a number: " + argv[i + 1]);
            a.options[s.substr(2)] = v;
            ++i;
        } else {
            a.positional.push_back(s);
        }
    }
    return a;
}

bool sameSize(const Image& a, const Image& b, const std::string& what)
{
    if (a.width == b.width && a.height == b.height)
        return true;
    std::printf("FAIL %s: sizes differ: %dx%d and %dx%d\n", what.c_str(), a.width, a.height, b.width, b.height);
    return false;
}

// Compares RGB (alpha is 1 in every file the program writes) of a rectangle of `ref` at (x0, y0)
// with all of `other`.
void compareRegion(const Image& ref, int x0, int y0, const Image& other, double halfUlps, Difference& d)
{
    for (int y = 0; y < other.height; ++y)
        for (int x = 0; x < other.width; ++x) {
            const float* a = ref.pixel(x0 + x, y0 + y);
            const float* b = other.pixel(x, y);
            for (int c = 0; c < 3; ++c)
                d.add(a[c], b[c], halfUlps);
        }
}

// Proves the comparison can fail: a copy of `image` with its brightest channel moved by two
// half ulps must be reported (otherwise a broken comparison would pass every test).
bool comparisonIsSensitive(const Image& image, double halfUlps)
{
    Image changed = image;
    if (changed.rgba.empty())
        return false;
    std::size_t brightest = 0; // among the compared channels, RGB
    for (std::size_t i = 0; i < changed.rgba.size(); ++i)
        if (i % 4 != 3 && changed.rgba[i] > changed.rgba[brightest])
            brightest = i;
    changed.rgba[brightest] += static_cast<float>((halfUlps + 2) * halfUlp(changed.rgba[brightest]));
    Difference d;
    compareRegion(image, 0, 0, changed, halfUlps, d);
    return d.failingChannels == 1;
}

int diffCommand(int argc, char** argv)
{
    const Args a = parseArgs(argc, argv, {"half-ulps"});
    if (a.positional.size() != 2)
        usage("diff REF.exr OTHER.exr [--half-ulps N]");
    const double halfUlps = a.option("half-ulps", 0);
    const Image ref = aurorawall::io::readExr(a.positional[0]);
    const Image other = aurorawall::io::readExr(a.positional[1]);
    if (!sameSize(ref, other, "diff"))
        return 1;
    Difference d;
    compareRegion(ref, 0, 0, other, halfUlps, d);
    d.print("diff");
    if (!comparisonIsSensitive(ref, halfUlps)) {
        std::printf("FAIL diff: the comparison does not detect a changed pixel\n");
        return 1;
    }
    if (d.failingChannels) {
        std::printf("FAIL diff: %ld channels differ by more than %g half ulps\n", d.failingChannels, halfUlps);
        return 1;
    }
    return 0;
}

int contentCommand(int argc, char** argv)
{
    const Args a = parseArgs(argc, argv, {"min-max", "min-lit-screens", "lit-above"});
    if (a.positional.size() != 2)
        usage("content IMAGE.exr WALL.toml [--min-max V] [--min-lit-screens K] [--lit-above L]");
    const Image image = aurorawall::io::readExr(a.positional[0]);
    const aurorawall::wall::Wall wall = aurorawall::wall::loadWall(a.positional[1]);
    const double minMax = a.option("min-max", 1e-3);
    const int minLit = static_cast<int>(a.option("min-lit-screens", 1));
    const float litAbove = static_cast<float>(a.option("lit-above", 1e-4));

    const std::size_t nonFinite = aurorawall::io::countNonFinite(image);
    double maxValue = 0;
    long clamped = 0;
    for (std::size_t i = 0; i < image.rgba.size(); ++i) {
        if (i % 4 == 3)
            continue;
        maxValue = std::max(maxValue, double(image.rgba[i]));
        if (std::abs(image.rgba[i]) >= kHalfMax)
            ++clamped;
    }
    if (image.width != wall.canvasSizePx.x || image.height != wall.canvasSizePx.y) {
        std::printf("FAIL content: image is %dx%d, the wall's canvas %dx%d\n", image.width, image.height,
                    wall.canvasSizePx.x, wall.canvasSizePx.y);
        return 1;
    }
    // The image is either the gathered canvas or a single screen of the canvas's size.
    int litScreens = 0;
    std::string perScreen;
    for (const auto& screen : wall.screens) {
        long lit = 0;
        for (int y = 0; y < screen.heightPx; ++y)
            for (int x = 0; x < screen.widthPx; ++x) {
                const float* p = image.pixel(screen.canvasOffsetPx.x + x, screen.canvasOffsetPx.y + y);
                if (std::max({p[0], p[1], p[2]}) > litAbove)
                    ++lit;
            }
        const double fraction = double(lit) / (double(screen.widthPx) * screen.heightPx);
        if (fraction >= 0.01 && fraction <= 0.99)
            ++litScreens;
        char buffer[128];
        std::snprintf(buffer, sizeof buffer, " %s:%.1f%%", screen.name.c_str(), 100 * fraction);
        perScreen += buffer;
    }
    std::printf("content: %dx%d max=%.6g non_finite=%zu clamped=%ld lit_screens=%d of %zu (pixels above %g:%s)\n",
                image.width, image.height, maxValue, nonFinite, clamped, litScreens, wall.screens.size(),
                double(litAbove), perScreen.c_str());
    bool ok = true;
    if (nonFinite || clamped) {
        std::printf("FAIL content: non-finite or clamped values\n");
        ok = false;
    }
    if (!(maxValue >= minMax)) {
        std::printf("FAIL content: brightest channel %g < %g: the image is (nearly) black\n", maxValue, minMax);
        ok = false;
    }
    if (litScreens < minLit) {
        std::printf("FAIL content: only %d screens have structure, wanted %d\n", litScreens, minLit);
        ok = false;
    }
    return ok ? 0 : 1;
}

int bezelCommand(int argc, char** argv)
{
    const Args a = parseArgs(argc, argv, {"half-ulps"});
    if (a.positional.size() != 3)
        usage("bezel WALL.toml REF.exr GATHERED.exr [--half-ulps N]");
    const aurorawall::wall::Wall wall = aurorawall::wall::loadWall(a.positional[0]);
    const Image ref = aurorawall::io::readExr(a.positional[1]);
    const Image gathered = aurorawall::io::readExr(a.positional[2]);
    const double halfUlps = a.option("half-ulps", 0);
    if (!sameSize(ref, gathered, "bezel"))
        return 1;
    if (ref.width != wall.canvasSizePx.x || ref.height != wall.canvasSizePx.y) {
        std::printf("FAIL bezel: images are %dx%d, the wall's canvas %dx%d\n", ref.width, ref.height,
                    wall.canvasSizePx.x, wall.canvasSizePx.y);
        return 1;
    }
    std::vector<char> inScreen(std::size_t(ref.width) * ref.height, 0);
    Difference screens;
    for (const auto& s : wall.screens) {
        const Image tile = aurorawall::io::crop(gathered, s.canvasOffsetPx.x, s.canvasOffsetPx.y, s.widthPx, s.heightPx);
        compareRegion(ref, s.canvasOffsetPx.x, s.canvasOffsetPx.y, tile, halfUlps, screens);
        for (int y = 0; y < s.heightPx; ++y)
            for (int x = 0; x < s.widthPx; ++x)
                inScreen[std::size_t(s.canvasOffsetPx.y + y) * ref.width + s.canvasOffsetPx.x + x] = 1;
    }
    long bezelPixels = 0, nonBlackBezel = 0, litInReference = 0;
    for (int y = 0; y < ref.height; ++y)
        for (int x = 0; x < ref.width; ++x) {
            if (inScreen[std::size_t(y) * ref.width + x])
                continue;
            ++bezelPixels;
            const float* g = gathered.pixel(x, y);
            if (g[0] != 0.0f || g[1] != 0.0f || g[2] != 0.0f)
                ++nonBlackBezel;
            const float* r = ref.pixel(x, y);
            if (std::max({r[0], r[1], r[2]}) > 1e-4f)
                ++litInReference;
        }
    screens.print("bezel: screen pixels");
    std::printf("bezel: %ld bezel pixels, %ld not black in the wall image, %ld lit in the single-screen reference\n",
                bezelPixels, nonBlackBezel, litInReference);
    bool ok = true;
    if (screens.failingChannels) {
        std::printf("FAIL bezel: %ld screen channels differ by more than %g half ulps\n", screens.failingChannels,
                    halfUlps);
        ok = false;
    }
    if (bezelPixels == 0) {
        std::printf("FAIL bezel: the wall has no bezel pixels\n");
        ok = false;
    }
    if (nonBlackBezel) {
        std::printf("FAIL bezel: bezel pixels are not black\n");
        ok = false;
    }
    if (litInReference == 0) {
        std::printf("FAIL bezel: the reference is black where the bezels are: the test proves nothing\n");
        ok = false;
    }
    return ok ? 0 : 1;
}

int tilesCommand(int argc, char** argv)
{
    const Args a = parseArgs(argc, argv, {"half-ulps"});
    if (a.positional.size() != 3)
        usage("tiles WALL.toml REF.exr TILE_DIR [--half-ulps N]");
    const aurorawall::wall::Wall wall = aurorawall::wall::loadWall(a.positional[0]);
    const Image ref = aurorawall::io::readExr(a.positional[1]);
    const double halfUlps = a.option("half-ulps", 0);
    Difference all;
    for (const auto& s : wall.screens) {
        const Image tile = aurorawall::io::readExr(a.positional[2] + "/tile-" + s.name + ".exr");
        if (tile.width != s.widthPx || tile.height != s.heightPx) {
            std::printf("FAIL tiles: tile-%s.exr is %dx%d, the screen %dx%d\n", s.name.c_str(), tile.width,
                        tile.height, s.widthPx, s.heightPx);
            return 1;
        }
        if (s.canvasOffsetPx.x + s.widthPx > ref.width || s.canvasOffsetPx.y + s.heightPx > ref.height) {
            std::printf("FAIL tiles: screen %s leaves the %dx%d reference\n", s.name.c_str(), ref.width, ref.height);
            return 1;
        }
        Difference d;
        compareRegion(ref, s.canvasOffsetPx.x, s.canvasOffsetPx.y, tile, halfUlps, d);
        compareRegion(ref, s.canvasOffsetPx.x, s.canvasOffsetPx.y, tile, halfUlps, all);
        d.print(("tiles: " + s.name).c_str());
    }
    all.print("tiles: all");
    if (all.failingChannels) {
        std::printf("FAIL tiles: %ld channels differ by more than %g half ulps\n", all.failingChannels, halfUlps);
        return 1;
    }
    return 0;
}

} // namespace

int domeCommand(int argc, char** argv)
{
    const Args a = parseArgs(argc, argv, {});
    if (a.positional.size() != 2)
        usage("dome WALL.toml IMAGE.exr");
    const aurorawall::wall::Wall wall = aurorawall::wall::loadWall(a.positional[0]);
    const Image image = aurorawall::io::readExr(a.positional[1]);
    if (wall.projection != aurorawall::wall::Projection::dome || image.width != wall.canvasSizePx.x ||
        image.height != wall.canvasSizePx.y) {
        std::printf("FAIL dome: need a dome wall and an image of its canvas size\n");
        return 1;
    }
    const aurorawall::wall::TileRays rays = aurorawall::wall::tileRays(wall, 0);
    long outside = 0, nonBlackOutside = 0, litInside = 0;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const float* p = image.pixel(x, y);
            const bool black = p[0] == 0.0f && p[1] == 0.0f && p[2] == 0.0f;
            if (aurorawall::wall::domeDirection(rays, {x + 0.5, y + 0.5}) == glm::dvec3(0.0)) {
                ++outside;
                nonBlackOutside += !black;
            } else {
                litInside += !black;
            }
        }
    std::printf("dome: %ld pixels outside the circle, %ld of them not black; %ld lit inside\n", outside,
                nonBlackOutside, litInside);
    return outside > 0 && nonBlackOutside == 0 && litInside > 0 ? 0 : 1;
}

int main(int argc, char** argv)
{
    if (argc < 2)
        usage("a command: diff, content, bezel, tiles or dome");
    const std::string command = argv[1];
    try {
        if (command == "diff")
            return diffCommand(argc, argv);
        if (command == "content")
            return contentCommand(argc, argv);
        if (command == "bezel")
            return bezelCommand(argc, argv);
        if (command == "tiles")
            return tilesCommand(argc, argv);
        if (command == "dome")
            return domeCommand(argc, argv);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "compare_walls: %s\n", e.what());
        return 2;
    }
    usage("unknown command " + command);
}
