#pragma once
// The MPI calls of the frame loop, in one place. Every rank runs the same binary, so
// trivially copyable structs travel as bytes.
#include "cluster/frame_state.h"
#include "cluster/frame_stats.h"

#include <mpi.h>

#include <cstdint>
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

    // Called by every rank after a set-up step with its own exit status (0: it went well) and error
    // message. Returns the largest status over the ranks, on every rank; if it is not 0, rank 0 prints
    // each distinct message once on stderr as "PREFIX: message" (or, if only some ranks failed,
    // "PREFIX: rank 2: message").
    int agreedStatus(int myStatus, const std::string& myError, const std::string& prefix) const;

    void broadcast(FrameState& state) const;
    // Rank 0's values to every rank (the size must already match on every rank).
    void broadcast(std::vector<int>& values) const;
    // Rank 0 receives one report from each rank, in rank order (others get an empty vector).
    std::vector<RankReport> gatherReports(const RankReport& mine) const;
    // All ranks wait here before their screens flip: the swap barrier.
    void swapBarrier() const;

    // Rank 0 receives every rank's bytes, concatenated in rank order, with their sizes.
    std::vector<char> gatherBytes(const std::vector<char>& mine, std::vector<int>& sizesOut) const;

    // Point-to-point messages of 16-bit words (band pixels as halves, io/half_pixels.h): every rank
    // posts what it sends and what it expects (buffers sized by the caller) at once, so no order of
    // sends can deadlock.
    struct Message {
        int rank = 0; // destination (outgoing) or source (incoming)
        int tag = 0;
        std::vector<std::uint16_t>* values = nullptr;
    };
    void exchange(const std::vector<Message>& outgoing, const std::vector<Message>& incoming) const;

private:
    int rank_ = 0;
    int size_ = 1;
};

} // namespace aurorawall::cluster
