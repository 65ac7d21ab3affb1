#pragma once
// The master's record of each rank's heartbeats: which ranks have been silent for longer than the
// timeout, and which are alive but hung. Pure bookkeeping (times in seconds on any monotonic clock),
// no MPI.
//
// Silence: every rank sends a heartbeat a few times per timeout from a thread of its own while its
// main thread draws, so a rank that is merely slow (an oversubscribed machine, an expensive frame)
// keeps being heard, and only a rank whose whole process stopped (SIGSTOP, a frozen host, a lost
// network) falls silent.
//
// Hung: the heartbeat also carries how long the rank's main thread has gone without progress
// (cluster/rank_phase.h, MainThreadProgress). A rank is hung when all of these hold:
//   - the master's main thread is waiting for the other ranks (a broadcast, gather, exchange or barrier);
//   - the job has completed at least one frame (the master's slowest frame is known);
//   - the rank's last heartbeat says it is in the frame loop (waiting for a frame, drawing, or in the
//     gather; set-up and the outputs are watched for silence only), not waiting for other ranks,
//     and without progress for longer than
//       max(timeout, 4 x max(the master's slowest completed frame, the master's own busy time in its
//           current frame)).
// A rank waiting for the hung one is inside a wait, so only the hung one is named. The multiple of
// the frame times keeps a wall whose frames all slow down (an oversubscribed machine, a frame that
// legitimately costs more) from being taken for hung: the master's own share of the work slows too.
#include "cluster/rank_phase.h"

#include <cstdint>
#include <vector>

namespace aurorawall::cluster {

// How many of the slowest frame a main thread may go without progress before it counts as hung.
constexpr double kFramesBeforeHung = 4.0;

class SilenceWatch {
public:
    // Ranks 0 .. rankCount-1, all heard at `startS` in set-up; rank 0 (the watcher itself) is never
    // silent or hung.
    SilenceWatch(int rankCount, double timeoutS, double startS);

    // What a heartbeat says about its rank's main thread.
    struct Heartbeat {
        RankPhase phase = RankPhase::SetUp;
        std::uint64_t frame = 0;
        bool waiting = false;  // inside a wait for other ranks
        double stalledS = 0.0; // without progress, outside waits
    };
    // A heartbeat from `rank` at `nowS`. A rank that said Finished is no longer watched.
    void heard(int rank, const Heartbeat& beat, double nowS);

    struct Silent {
        int rank = 0;
        double silentS = 0.0;    // since its last heartbeat
        RankPhase phase = RankPhase::SetUp; // what its last heartbeat said
        std::uint64_t frame = 0;
    };
    // The ranks not heard for longer than the timeout at `nowS`, in rank order.
    std::vector<Silent> silentRanks(double nowS) const;
    // Each rank's seconds since its last heartbeat at `nowS` (since the start until its first), in
    // rank order; 0 for rank 0, the watcher itself.
    std::vector<double> heartbeatAgesS(double nowS) const;

    // How long a main thread may go without progress before it counts as hung, given the master's.
    double stallLimitS(const MainThreadProgress::Snapshot& master) const;
    struct Hung {
        int rank = 0;
        Heartbeat beat; // its last heartbeat
    };
    // The hung ranks, by the rule above, given the master's main thread now; in rank order.
    std::vector<Hung> hungRanks(const MainThreadProgress::Snapshot& master) const;

private:
    struct Heard {
        double atS = 0.0;
        Heartbeat beat;
    };
    double timeoutS_;
    std::vector<Heard> ranks_;
};

} // namespace aurorawall::cluster
