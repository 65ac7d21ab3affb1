#pragma once
// Never hang on a rank that stopped answering or whose main thread is stuck. Every rank but the
// master runs a thread that sends the master a heartbeat (its phase and frame, and how long its main
// thread has gone without progress, cluster/rank_phase.h) every timeout/5 seconds (at most every
// second, at least every 50 ms); the master runs a thread that receives them and, when a rank has
// been silent for longer than the timeout, or is hung by the rule of cluster/silence_watch.h (its
// main thread without progress, outside any wait for other ranks, for longer than both the timeout
// and 4 times the slowest frame, while the master waits), prints one line naming the rank, what it
// was last doing and where the master waits, and ends the whole job with
// MPI_Abort(kRankSilentExitStatus).
//
// A thread of its own measures the silence of the process, not the frame time: a rank busy in a
// long draw, or starved of CPU on an oversubscribed machine, still sends its heartbeats, and the
// hung-rank rule allows for frames that all slow down. A rank that dies ends the job through Open MPI
// itself. The master is watched too: its thread sends every worker a heartbeat at the same period
// (and a last one when it finishes), and a worker that hears none for longer than the timeout (the
// master stopped, frozen or cut off, while the workers wait for it in the frame's broadcast) prints
// one line naming the master and itself and ends the job with MPI_Abort(kRankSilentExitStatus).
//
// Test hook: the environment variable AURORAWALL_TEST_HANG_MAIN_THREAD=RANK:FRAME makes rank RANK's
// main thread sleep for ever when it starts drawing frame FRAME, as a driver call that never returns
// would (its heartbeat thread keeps beating). It is read once, when the watchdog starts.
#include "cluster/rank_phase.h"
#include "cluster/silence_watch.h"

#include <mpi.h>

#include <atomic>
#include <cstdint>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

namespace aurorawall::cluster {

// The exit status of a job ended because a rank fell silent or hung.
constexpr int kRankSilentExitStatus = 3;

// Seconds between two heartbeats of a rank (and of the master to the workers): a fifth of the
// timeout, within [0.05, 1] s.
double heartbeatPeriodS(double timeoutS);

class Watchdog {
public:
    // Gathers every rank's host name (collective on `comm`: every rank makes its watchdog at once)
    // and starts the thread; `comm` is a communicator of its own (a duplicate of MPI_COMM_WORLD), so
    // its messages never meet the frame's. Needs MPI_THREAD_MULTIPLE.
    Watchdog(MPI_Comm comm, double timeoutS);
    // Tells the master this rank has finished (workers) or stops watching (master), and joins the thread.
    ~Watchdog();
    Watchdog(const Watchdog&) = delete;
    Watchdog& operator=(const Watchdog&) = delete;

    // What the main thread is doing now; the next heartbeat carries it (on the master: named in the
    // line printed when a rank falls silent or hangs). A change of phase is progress.
    void setPhase(RankPhase phase, std::uint64_t frame);
    // The main thread enters and leaves a wait for other ranks (see WaitingForRanks).
    void waitBegins();
    void waitEnds();

    // On the master: each rank's seconds since its last heartbeat, in rank order (0 for the master
    // itself; SilenceWatch::heartbeatAgesS). Empty on the other ranks. Any thread.
    std::vector<double> heartbeatAgesS();

private:
    void sendHeartbeats();
    void watchRanks();
    MainThreadProgress::Snapshot progress();

    MPI_Comm comm_;
    std::vector<std::string> hosts_; // each rank's host (MPI_Get_processor_name)
    int rank_ = 0;
    int size_ = 1;
    double timeoutS_;
    int hangRank_ = -1; // the test hook's rank and frame
    std::uint64_t hangFrame_ = 0;
    std::mutex mutex_; // guards progress_, marked by the main thread and read by the watchdog's
    MainThreadProgress progress_;
    std::mutex watchMutex_;              // guards watch_, fed by the watchdog's thread, read by heartbeatAgesS
    std::optional<SilenceWatch> watch_;  // the master's record of the heartbeats
    std::atomic<bool> stop_{false};
    std::thread thread_;
};

// While it lives, the main thread waits for other ranks (a broadcast, gather, exchange or barrier),
// which the hung-rank rule does not count as being stuck. `watchdog` may be null (no watchdog).
class WaitingForRanks {
public:
    explicit WaitingForRanks(Watchdog* watchdog);
    ~WaitingForRanks();
    WaitingForRanks(const WaitingForRanks&) = delete;
    WaitingForRanks& operator=(const WaitingForRanks&) = delete;

private:
    Watchdog* watchdog_;
};

} // namespace aurorawall::cluster
