#include "cluster/load_balancer.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

namespace aurorawall::cluster {

std::vector<Band> makeBands(const wall::Wall& wall, int bandsPerScreen)
{
    if (bandsPerScreen < 1)
        throw std::invalid_argument("bands per screen must be at least 1");
    std::vector<Band> bands;
    for (int s = 0; s < static_cast<int>(wall.screens.size()); ++s) {
        const wall::Screen& screen = wall.screens[s];
        const int blocks = std::max(screen.heightPx / kBandRowBlock, 1);
        const int count = std::min(bandsPerScreen, blocks);
        auto boundary = [&](int b) {
            return b == count ? screen.heightPx : kBandRowBlock * static_cast<int>(std::lround(double(b) * blocks / count));
        };
        for (int b = 0; b < count; ++b)
            bands.push_back({s, boundary(b), boundary(b + 1) - boundary(b), screen.rank});
    }
    return bands;
}

LoadBalancer::LoadBalancer(std::vector<Band> bands, int ranks, double levelWeight, double trendWeight)
    : bands_(std::move(bands)), ranks_(ranks), levelWeight_(levelWeight), trendWeight_(trendWeight),
      level_(bands_.size(), 0.0), trend_(bands_.size(), 0.0)
{
    for (const Band& b : bands_)
        previous_.push_back(b.owner);
}

void LoadBalancer::observe(const std::vector<double>& bandCost)
{
    for (size_t i = 0; i < level_.size(); ++i) {
        if (!std::isfinite(bandCost[i]))
            continue;
        if (measurements_ == 0) {
            level_[i] = bandCost[i];
            continue;
        }
        // Holt: L' = a x + (1 - a)(L + T), T' = b (L' - L) + (1 - b) T.
        const double level = levelWeight_ * bandCost[i] + (1.0 - levelWeight_) * (level_[i] + trend_[i]);
        trend_[i] = trendWeight_ * (level - level_[i]) + (1.0 - trendWeight_) * trend_[i];
        level_[i] = level;
    }
    ++measurements_;
}

std::vector<double> LoadBalancer::predictedCosts() const
{
    std::vector<double> predicted(level_.size());
    for (size_t i = 0; i < level_.size(); ++i)
        predicted[i] = std::max(level_[i] + trend_[i], 0.0);
    return predicted;
}

std::vector<int> LoadBalancer::assign(double tolerance)
{
    if (measurements_ == 0)
        return previous_;
    const std::vector<double> cost = predictedCosts();
    const double total = std::accumulate(cost.begin(), cost.end(), 0.0);
    const double limit = (1.0 + tolerance) * total / ranks_;
    std::vector<size_t> order(bands_.size());
    std::iota(order.begin(), order.end(), size_t(0));
    std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) { return cost[a] > cost[b]; });
    std::vector<double> load(static_cast<size_t>(ranks_), 0.0);
    std::vector<int> assignment(bands_.size(), 0);
    for (size_t i : order) {
        const double c = cost[i];
        int rank = previous_[i];
        if (load[rank] + c > limit)
            rank = bands_[i].owner;
        if (load[rank] + c > limit)
            rank = static_cast<int>(std::min_element(load.begin(), load.end()) - load.begin());
        load[rank] += c;
        assignment[i] = rank;
    }
    previous_ = assignment;
    return assignment;
}

} // namespace aurorawall::cluster
