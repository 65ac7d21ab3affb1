#pragma once
// Which rank draws each band, decided by the master every frame: the static split (every band by its
// screen's rank) or the load balancer's (cluster/load_balancer.h), which follows the bands' costs
// the ranks report.
#include "cluster/load_balancer.h"
#include "cluster/rank_message.h"

#include <cstdint>
#include <optional>
#include <vector>

namespace aurorawall::app {

class BandSplit {
public:
    // balanced: the load balancer splits the bands by `measure`; otherwise the split stays static.
    BandSplit(const std::vector<cluster::Band>& bands, int ranks, bool balanced, cluster::BandMeasure measure);

    // The rank that draws each band this frame.
    std::vector<std::int32_t> next();

    // The ranks' reports of the frame just drawn (the static split ignores them).
    void observe(const std::vector<cluster::RankMessage>& reports);

private:
    std::vector<std::int32_t> owners_;
    std::optional<cluster::LoadBalancer> balancer_;
    cluster::BandMeasure measure_;
};

} // namespace aurorawall::app
