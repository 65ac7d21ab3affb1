// check_cost_map: checks the PNG of `render --cost-map` against the wall's radiance, for the end-to-end test.
//
//   check_cost_map COST.png WALL.exr
//
// COST.png must be the wall's width and its height plus the scale bar, and every wall pixel must be
// a colour of the map (viridis, within one 8-bit code). Each pixel's place on the map (0 cheapest,
// 1 costliest, log scale) is read back by the nearest viridis colour. The aurora's curtains, the
// 1% brightest green pixels of WALL.exr whose green is at least twice red and blue, must sit higher
// on the map than the empty sky: the pixels of the top tenth of the wall whose radiance is below 1%
// of that green threshold in every channel (no curtain, no star). Prints both means; exits 0 when
// the curtains' mean place exceeds the sky's by at least 0.2, 1 when not, 2 on bad usage or files.
#include "app/cost_map.h"
#include "io/exr.h"
#include "io/png.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <vector>

using namespace aurorawall;

namespace {

constexpr int kSteps = 1024;

// The place on the map of the nearest viridis colour, and its distance in 8-bit codes (largest channel).
std::pair<double, int> placeOnMap(const float* encoded)
{
    double best = 0.0;
    int bestDistance = 256;
    for (int i = 0; i <= kSteps; ++i) {
        const app::Rgb8 c = app::viridis(double(i) / kSteps);
        int d = 0;
        for (int k = 0; k < 3; ++k)
            d = std::max(d, std::abs(int(std::lround(255.0 * encoded[k])) - int(c[k])));
        if (d < bestDistance) {
            bestDistance = d;
            best = double(i) / kSteps;
        }
    }
    return {best, bestDistance};
}

} // namespace

int main(int argc, char** argv)
{
    if (argc != 3) {
        std::fprintf(stderr, "usage: check_cost_map COST.png WALL.exr\n");
        return 2;
    }
    io::Image map, wall;
    try {
        map = io::readPng8(argv[1]);
        wall = io::readExr(argv[2]);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "check_cost_map: %s\n", e.what());
        return 2;
    }
    if (map.width != wall.width || map.height != wall.height + app::scaleBarHeight(wall.width)) {
        std::printf("FAIL: cost map %dx%d, expected %dx%d\n", map.width, map.height, wall.width,
                    wall.height + app::scaleBarHeight(wall.width));
        return 1;
    }

    std::vector<float> greens;
    for (int y = 0; y < wall.height; ++y)
        for (int x = 0; x < wall.width; ++x)
            greens.push_back(wall.pixel(x, y)[1]);
    std::nth_element(greens.begin(), greens.begin() + greens.size() * 99 / 100, greens.end());
    const float curtainGreen = greens[greens.size() * 99 / 100];

    double curtainSum = 0.0, skySum = 0.0;
    int curtains = 0, sky = 0, offMap = 0;
    for (int y = 0; y < wall.height; ++y)
        for (int x = 0; x < wall.width; ++x) {
            const auto [place, distance] = placeOnMap(map.pixel(x, y));
            offMap += distance > 1;
            const float* r = wall.pixel(x, y);
            if (r[1] >= curtainGreen && r[1] >= 2 * r[0] && r[1] >= 2 * r[2]) {
                curtainSum += place;
                ++curtains;
            } else if (y < wall.height / 10 && std::max({r[0], r[1], r[2]}) < 0.01f * curtainGreen) {
                skySum += place;
                ++sky;
            }
        }
    const double curtainMean = curtains ? curtainSum / curtains : 0.0, skyMean = sky ? skySum / sky : 1.0;
    std::printf("curtain pixels %d mean place %.3f, empty sky pixels %d mean place %.3f, off the map %d\n", curtains,
                curtainMean, sky, skyMean, offMap);
    if (offMap > 0 || curtains < 100 || sky < 100 || curtainMean < skyMean + 0.2) {
        std::printf("FAIL\n");
        return 1;
    }
    return 0;
}
