#pragma once
// The master's record of when it last heard from each rank, and which ranks have been silent for
// longer than the timeout. Pure bookkeeping (times in seconds on any monotonic clock), no MPI.
//
// The timeout measures a rank's silence, not its frame time: every rank sends a heartbeat a few
// times per timeout from a thread of its own while its main thread draws, so a rank that is merely
// slow (an oversubscribed machine, an expensive frame) keeps being heard, and only a rank whose
// whole process stopped (SIGSTOP, a frozen host, a lost network) falls silent.
#include "cluster/rank_phase.h"

#include <cstdint>
#include <vector>

namespace aurorawall::cluster {

class SilenceWatch {
public:
    // Ranks 0 .. rankCount-1, all heard at `startS` in set-up; rank 0 (the watcher itself) is never silent.
    SilenceWatch(int rankCount, double timeoutS, double startS);

    // A heartbeat from `rank` at `nowS` saying what it is doing. A rank that said Finished is no
    // longer watched.
    void heard(int rank, RankPhase phase, std::uint64_t frame, double nowS);

    struct Silent {
        int rank = 0;
        double silentS = 0.0;    // since its last heartbeat
        RankPhase phase = RankPhase::SetUp; // what its last heartbeat said
        std::uint64_t frame = 0;
    };
    // The ranks not heard for longer than the timeout at `nowS`, in rank order.
    std::vector<Silent> silentRanks(double nowS) const;

private:
    struct Heard {
        double atS = 0.0;
        RankPhase phase = RankPhase::SetUp;
        std::uint64_t frame = 0;
    };
    double timeoutS_;
    std::vector<Heard> ranks_;
};

} // namespace aurorawall::cluster
