#include "app/band_split.h"

namespace aurorawall::app {

BandSplit::BandSplit(const std::vector<cluster::Band>& bands, int ranks, bool balanced, cluster::BandMeasure measure)
    : measure_(measure)
{
    for (const cluster::Band& b : bands)
        owners_.push_back(b.owner);
    if (balanced)
        balancer_.emplace(bands, ranks);
}

std::vector<std::int32_t> BandSplit::next()
{
    if (!balancer_)
        return owners_;
    const std::vector<int> assignment = balancer_->assign();
    return {assignment.begin(), assignment.end()};
}

void BandSplit::observe(const std::vector<cluster::RankMessage>& reports)
{
    if (balancer_)
        balancer_->observe(cluster::bandCosts(reports, owners_.size(), measure_));
}

} // namespace aurorawall::app
