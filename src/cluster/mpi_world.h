#pragma once
// The MPI calls of aurorawall, in one place: agreement on set-up errors, the frame's broadcast and
// gather, the swap barrier, the band exchange and the gathering of output. Messages travel as bytes
// (every rank runs the same binary). The watchdog (cluster/watchdog.h) ends the job if a rank falls
// silent or hangs; every call here that waits for other ranks tells it so (WaitingForRanks).
#include "cluster/rank_phase.h"
#include "cluster/watchdog.h"

#include <mpi.h>

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace aurorawall::cluster {

class MpiWorld {
public:
    MpiWorld(int* argc, char*** argv);
    ~MpiWorld();
    MpiWorld(const MpiWorld&) = delete;
    MpiWorld& operator=(const MpiWorld&) = delete;

    int rank() const { return rank_; }
    int size() const { return size_; }
    bool isMaster() const { return rank_ == 0; }
    // This rank's index among the ranks on its node (those that share memory with it), in rank order:
    // which of the node's GPUs it draws on (gl/device_order.h).
    int nodeRank() const { return nodeRank_; }

    // Ends every rank of the job with `status` (MPI_Abort): for a failure in the middle of a frame,
    // when the other ranks may be blocked waiting for this one.
    [[noreturn]] void abortJob(int status) const;

    // Collective: from now on the master ends the job if another rank sends no heartbeat for
    // `timeoutS` seconds (cluster/watchdog.h).
    void startWatchdog(double timeoutS) const;
    // What this rank is doing now, for its heartbeats (nothing before startWatchdog).
    void setPhase(RankPhase phase, std::uint64_t frame = 0) const;
    // On the master, with a watchdog: each rank's seconds since its last heartbeat (Watchdog::
    // heartbeatAgesS); otherwise empty.
    std::vector<double> heartbeatAgesS() const;

    // Called by every rank after a set-up step with its own exit status (0: it went well) and error
    // message. Returns the largest status over the ranks, on every rank; if it is not 0, rank 0 prints
    // each distinct message once on stderr as "PREFIX: message" (or, if only some ranks failed,
    // "PREFIX: rank 2: message").
    int agreedStatus(int myStatus, const std::string& myError, const std::string& prefix) const;

    // Rank 0's bytes to every rank, in one MPI_Bcast: every rank passes a buffer of the same size
    // (the frame's message, cluster/frame_message.h).
    void broadcast(std::vector<char>& bytes) const;
    // Rank 0's `value` on every rank.
    int broadcastInt(int value) const;
    // Every rank's bytes to rank 0, concatenated in rank order, in one MPI_Gather: every rank passes
    // the same size (its report, cluster/rank_message.h); the others get an empty vector.
    std::vector<char> gather(const std::vector<char>& mine) const;
    // Rank 0 receives every rank's bytes of any size, concatenated in rank order, with their sizes.
    std::vector<char> gatherBytes(const std::vector<char>& mine, std::vector<int>& sizesOut) const;
    // Every rank's string on rank 0, in rank order (gatherBytes); the others get an empty vector.
    std::vector<std::string> gatherStrings(const std::string& mine) const;

    // All ranks wait here before their windows flip, so that every screen of the wall shows the
    // same frame: the swap barrier (windows only; headless ranks are kept in step by the frame's
    // gather and broadcast).
    void swapBarrier() const;

    // Point-to-point messages of bytes (band pixels, compressed: io/band_compression.h): every rank
    // posts all it sends at once, then takes each message it expects, whatever its length (an
    // incoming buffer is resized to the message's), so no order of sends can deadlock.
    struct Message {
        int rank = 0; // destination (outgoing) or source (incoming)
        int tag = 0;
        std::vector<std::uint8_t>* bytes = nullptr;
    };
    void exchange(const std::vector<Message>& outgoing, const std::vector<Message>& incoming) const;

private:
    int rank_ = 0;
    int size_ = 1;
    int nodeRank_ = 0;
    MPI_Comm heartbeatComm_ = MPI_COMM_NULL;
    mutable std::unique_ptr<Watchdog> watchdog_; // started once the options are known
};

} // namespace aurorawall::cluster
