#include "cluster/rank_phase.h"

#include <algorithm>

namespace aurorawall::cluster {

std::string describePhase(RankPhase phase, std::uint64_t frame)
{
    const std::string n = std::to_string(frame);
    switch (phase) {
    case RankPhase::SetUp: return "set-up";
    case RankPhase::Broadcast: return "waiting for the frame after frame " + n;
    case RankPhase::Draw: return "drawing frame " + n;
    case RankPhase::Gather: return "the gather of frame " + n;
    case RankPhase::Output: return "writing the outputs";
    case RankPhase::Finished: return "finished";
    }
    return "an unknown phase";
}

} // namespace aurorawall::cluster

namespace aurorawall::cluster {

MainThreadProgress::MainThreadProgress(double startS) : progressS_(startS) {}

void MainThreadProgress::phaseChanged(RankPhase phase, std::uint64_t frame, double nowS)
{
    if (!waiting_)
        busyBeforeS_ += nowS - progressS_;
    if (phase == RankPhase::Draw) {
        if (frameStartS_ >= 0.0)
            slowestFrameS_ = std::max(slowestFrameS_, nowS - frameStartS_);
        frameStartS_ = nowS;
        busyBeforeS_ = 0.0;
    }
    phase_ = phase;
    frame_ = frame;
    progressS_ = nowS;
}

void MainThreadProgress::waitBegins(double nowS)
{
    if (!waiting_)
        busyBeforeS_ += nowS - progressS_;
    waiting_ = true;
    progressS_ = nowS;
}

void MainThreadProgress::waitEnds(double nowS)
{
    waiting_ = false;
    progressS_ = nowS;
}

MainThreadProgress::Snapshot MainThreadProgress::at(double nowS) const
{
    const double stalled = waiting_ ? 0.0 : nowS - progressS_;
    return {phase_, frame_, waiting_, stalled, slowestFrameS_, busyBeforeS_ + stalled};
}

} // namespace aurorawall::cluster
