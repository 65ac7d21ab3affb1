#include "cluster/silence_watch.h"

#include <algorithm>

namespace aurorawall::cluster {

namespace {

bool inFrameLoop(RankPhase phase)
{
    return phase == RankPhase::Broadcast || phase == RankPhase::Draw || phase == RankPhase::Gather;
}

} // namespace

SilenceWatch::SilenceWatch(int rankCount, double timeoutS, double startS)
    : timeoutS_(timeoutS), ranks_(static_cast<size_t>(rankCount), Heard{startS, {}})
{
}

void SilenceWatch::heard(int rank, const Heartbeat& beat, double nowS)
{
    if (rank < 0 || rank >= static_cast<int>(ranks_.size()))
        return;
    Heard& h = ranks_[static_cast<size_t>(rank)];
    if (h.beat.phase == RankPhase::Finished)
        return;
    h = {nowS, beat};
}

std::vector<SilenceWatch::Silent> SilenceWatch::silentRanks(double nowS) const
{
    std::vector<Silent> silent;
    for (size_t r = 1; r < ranks_.size(); ++r) {
        const Heard& h = ranks_[r];
        if (h.beat.phase != RankPhase::Finished && nowS - h.atS > timeoutS_)
            silent.push_back({static_cast<int>(r), nowS - h.atS, h.beat.phase, h.beat.frame});
    }
    return silent;
}

std::vector<double> SilenceWatch::heartbeatAgesS(double nowS) const
{
    std::vector<double> ages(ranks_.size(), 0.0);
    for (size_t r = 1; r < ranks_.size(); ++r)
        ages[r] = std::max(0.0, nowS - ranks_[r].atS);
    return ages;
}

double SilenceWatch::stallLimitS(const MainThreadProgress::Snapshot& master) const
{
    return std::max(timeoutS_, kFramesBeforeHung * std::max(master.slowestFrameS, master.busyThisFrameS));
}

std::vector<SilenceWatch::Hung> SilenceWatch::hungRanks(const MainThreadProgress::Snapshot& master) const
{
    std::vector<Hung> hung;
    if (!master.waiting || master.slowestFrameS <= 0.0)
        return hung;
    const double limitS = stallLimitS(master);
    for (size_t r = 1; r < ranks_.size(); ++r) {
        const Heartbeat& beat = ranks_[r].beat;
        if (inFrameLoop(beat.phase) && !beat.waiting && beat.stalledS > limitS)
            hung.push_back({static_cast<int>(r), beat});
    }
    return hung;
}

} // namespace aurorawall::cluster
