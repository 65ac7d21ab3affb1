#pragma once
// Never hang on a rank that stopped answering. Every rank but the master runs a thread that sends the
// master a heartbeat (its phase and frame, cluster/rank_phase.h) every timeout/5 seconds (at most
// every second, at least every 50 ms); the master runs a thread that receives them and, when a rank
// has been silent for longer than the timeout (cluster/silence_watch.h), prints one line naming the
// rank, what it was last doing and where the master waits, and ends the whole job with
// MPI_Abort(kRankSilentExitStatus).
//
// A thread of its own measures the silence of the process, not the frame time: a rank busy in a
// long draw, or starved of CPU on an oversubscribed machine, still sends its heartbeats. What it
// cannot see is a process that is alive but whose main thread is stuck (a hung driver call): its
// heartbeat thread keeps answering. A rank that dies ends the job through Open MPI itself. The
// master is not watched (the other ranks wait for it in the frame's broadcast).
#include "cluster/rank_phase.h"

#include <mpi.h>

#include <atomic>
#include <cstdint>
#include <thread>

namespace aurorawall::cluster {

// The exit status of a job ended because a rank fell silent.
constexpr int kRankSilentExitStatus = 3;

class Watchdog {
public:
    // Starts the thread; `comm` is a communicator of its own (a duplicate of MPI_COMM_WORLD), so its
    // messages never meet the frame's. Needs MPI_THREAD_MULTIPLE.
    Watchdog(MPI_Comm comm, double timeoutS);
    // Tells the master this rank has finished (workers) or stops watching (master), and joins the thread.
    ~Watchdog();
    Watchdog(const Watchdog&) = delete;
    Watchdog& operator=(const Watchdog&) = delete;

    // What the main thread is doing now; the next heartbeat carries it (on the master: named in the
    // line printed when a rank falls silent).
    void setPhase(RankPhase phase, std::uint64_t frame);

private:
    void sendHeartbeats();
    void watchRanks();

    MPI_Comm comm_;
    int rank_ = 0;
    int size_ = 1;
    double timeoutS_;
    std::atomic<std::int64_t> phase_{static_cast<std::int64_t>(RankPhase::SetUp)};
    std::atomic<std::uint64_t> frame_{0};
    std::atomic<bool> stop_{false};
    std::thread thread_;
};

} // namespace aurorawall::cluster
