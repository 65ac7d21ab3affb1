#include "cluster/rank_phase.h"

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
