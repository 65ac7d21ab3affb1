#include "cluster/silence_watch.h"

namespace aurorawall::cluster {

SilenceWatch::SilenceWatch(int rankCount, double timeoutS, double startS)
    : timeoutS_(timeoutS), ranks_(static_cast<size_t>(rankCount), Heard{startS, RankPhase::SetUp, 0})
{
}

void SilenceWatch::heard(int rank, RankPhase phase, std::uint64_t frame, double nowS)
{
    if (rank < 0 || rank >= static_cast<int>(ranks_.size()))
        return;
    Heard& h = ranks_[static_cast<size_t>(rank)];
    if (h.phase == RankPhase::Finished)
        return;
    h = {nowS, phase, frame};
}

std::vector<SilenceWatch::Silent> SilenceWatch::silentRanks(double nowS) const
{
    std::vector<Silent> silent;
    for (size_t r = 1; r < ranks_.size(); ++r) {
        const Heard& h = ranks_[r];
        if (h.phase != RankPhase::Finished && nowS - h.atS > timeoutS_)
            silent.push_back({static_cast<int>(r), nowS - h.atS, h.phase, h.frame});
    }
    return silent;
}

} // namespace aurorawall::cluster
