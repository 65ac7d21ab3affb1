#include "cluster/load_balancer.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>

using namespace aurorawall;

namespace {

// A 2x1 wall, one rank per screen, 8 bands per screen.
std::vector<cluster::Band> twoScreens()
{
    wall::GridSpec grid;
    grid.columns = 2;
    grid.screenPx = {64, 70};
    grid.screenMm = {64.0, 70.0};
    return cluster::makeBands(wall::makeGridWall(grid), 8);
}

std::vector<double> loads(const std::vector<int>& assignment, const std::vector<double>& cost, int ranks)
{
    std::vector<double> load(ranks, 0.0);
    for (size_t i = 0; i < assignment.size(); ++i)
        load[assignment[i]] += cost[i];
    return load;
}

} // namespace

TEST(LoadBalancer, BandsCoverEveryRowOnce)
{
    const std::vector<cluster::Band> bands = twoScreens();
    ASSERT_EQ(bands.size(), 16u);
    int rows = 0;
    for (const cluster::Band& b : bands)
        rows += b.height;
    EXPECT_EQ(rows, 2 * 70);
    EXPECT_EQ(bands[8].screen, 1);
    EXPECT_EQ(bands[8].owner, 1);
    EXPECT_EQ(bands[8].y0, 0);
    EXPECT_EQ(bands[7].y0 + bands[7].height, 70);
    for (size_t i = 0; i < bands.size(); ++i) {
        EXPECT_EQ(bands[i].y0 % cluster::kBandRowBlock, 0) << "band " << i;
        EXPECT_GE(bands[i].height, cluster::kBandRowBlock) << "band " << i;
        if (i % 8 != 7) {
            EXPECT_EQ(bands[i].height % cluster::kBandRowBlock, 0) << "band " << i;
        }
    }
}

// Fewer blocks than bands asked for: one band per block; a screen shorter than a block: one band.
TEST(LoadBalancer, ShortScreensGetFewerBands)
{
    wall::GridSpec grid;
    grid.screenPx = {64, 37};
    grid.screenMm = {64.0, 37.0};
    const std::vector<cluster::Band> bands = cluster::makeBands(wall::makeGridWall(grid), 8);
    ASSERT_EQ(bands.size(), 4u);
    EXPECT_EQ(bands[3].y0, 24);
    EXPECT_EQ(bands[3].height, 13);
    grid.screenPx = {64, 5};
    const std::vector<cluster::Band> one = cluster::makeBands(wall::makeGridWall(grid), 8);
    ASSERT_EQ(one.size(), 1u);
    EXPECT_EQ(one[0].height, 5);
}

TEST(LoadBalancer, StartsWithEveryBandAtHome)
{
    cluster::LoadBalancer balancer(twoScreens(), 2);
    const std::vector<int> a = balancer.assign();
    for (size_t i = 0; i < a.size(); ++i)
        EXPECT_EQ(a[i], balancer.bands()[i].owner);
}

TEST(LoadBalancer, MovesWorkFromTheExpensiveScreen)
{
    // Screen 0 costs 10 per band, screen 1 costs 1: static split 80 vs 8 (efficiency 55%).
    cluster::LoadBalancer balancer(twoScreens(), 2);
    std::vector<double> cost(16, 1.0);
    std::fill(cost.begin(), cost.begin() + 8, 10.0);
    balancer.observe(cost);
    const std::vector<double> load = loads(balancer.assign(), cost, 2);
    const double mean = 0.5 * (load[0] + load[1]);
    EXPECT_LE(std::max(load[0], load[1]) / mean, 1.15) << load[0] << " " << load[1];
}

TEST(LoadBalancer, DampedAndStableUnderSteadyCost)
{
    // Under the same measured costs the assignment settles and stays (no oscillation). A single outlier
    // frame (10 → 30) moves Holt's level 0.8 of the way, 10 → 26, and its trend 0.3 of the level's
    // move, 0 → 4.8: predicted 30.8. The next ordinary frame (10) pulls it back at once: level
    // 0.8·10 + 0.2·30.8 = 14.16, trend 0.3·(14.16 − 26) + 0.7·4.8 = −0.192, predicted 13.968. A few
    // roundings in double: 1e-12 relative.
    cluster::LoadBalancer balancer(twoScreens(), 2);
    std::vector<double> cost(16, 1.0);
    std::fill(cost.begin(), cost.begin() + 8, 10.0);
    balancer.observe(cost);
    std::vector<int> last = balancer.assign();
    for (int frame = 0; frame < 10; ++frame) {
        balancer.observe(cost);
        const std::vector<int> next = balancer.assign();
        EXPECT_EQ(next, last) << "frame " << frame;
        last = next;
    }
    std::vector<double> spike = cost;
    spike[0] = 30.0;
    balancer.observe(spike);
    EXPECT_NEAR(balancer.predictedCosts()[0], 30.8, 1e-12 * 30.8);
    balancer.observe(cost);
    EXPECT_NEAR(balancer.predictedCosts()[0], 13.968, 1e-12 * 13.968);
}

TEST(LoadBalancer, FollowsACostThatKeepsDrifting)
{
    // A band whose cost grows by 1 every frame (the camera flying toward a curtain): the trend makes
    // the prediction catch up with the next frame's cost instead of lagging behind it.
    cluster::LoadBalancer balancer(twoScreens(), 2);
    std::vector<double> cost(16, 1.0);
    for (int frame = 0; frame < 30; ++frame) {
        cost[0] = 10.0 + frame;
        balancer.observe(cost);
    }
    EXPECT_NEAR(balancer.predictedCosts()[0], 10.0 + 30.0, 0.1);
}
