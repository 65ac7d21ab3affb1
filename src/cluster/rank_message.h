#pragma once
// What every rank sends the master once per frame, in one gather: its RankReport, the cost of each
// band it drew and the input events of its windows. The message has the same size on every rank
// (room for every band of the wall and kMaxInputEvents events), so the gather needs no sizes first.
#include "cluster/frame_message.h"
#include "cluster/frame_stats.h"

#include <cstdint>
#include <vector>

namespace aurorawall::cluster {

struct BandCost {
    std::int32_t band = 0;
    // Process CPU time to draw the run of bands it was drawn with, times its share of the run's work, ms.
    double cpuMs = 0.0;
    // The band's work: the sum over its pixels of 1 + the ray's aurora samples (shaders/render/main.frag).
    // Unlike CPU time it does not depend on who drew the band or on the machine's noise.
    double work = 0.0;
};

struct RankMessage {
    RankReport report;
    std::vector<BandCost> costs; // the bands it drew (none when nothing is balanced)
    std::vector<InputEvent> events; // keys and drags in its windows since its last message, at most kMaxInputEvents
};

// The size of every rank's message on a wall of `bandCount` bands.
std::size_t rankMessageBytes(std::size_t bandCount);

// The message as bytes of rankMessageBytes(bandCount): the report, the cost count, the event count,
// the costs, the events (zeros after the last). Throws std::invalid_argument for more costs than
// bands or more than kMaxInputEvents events.
std::vector<char> packRankMessage(const RankMessage& message, std::size_t bandCount);

// One message from rankMessageBytes(bandCount) bytes at `bytes`. Throws std::runtime_error if they
// do not hold one (a count beyond the bands or kMaxInputEvents, a band index outside the wall).
RankMessage unpackRankMessage(const char* bytes, std::size_t bandCount);

// The master's gather, split into the ranks' messages, in rank order.
std::vector<RankMessage> unpackRankMessages(const std::vector<char>& bytes, std::size_t bandCount);

// What the load balancer balances: each band's measured time (the GPU's from timer queries, or CPU time
// on Mesa's CPU renderers), or the rays' work.
enum class BandMeasure { Time, Work };

// Each band's cost by `measure` from the ranks' messages (NaN where no rank reported the band).
std::vector<double> bandCosts(const std::vector<RankMessage>& messages, std::size_t bandCount, BandMeasure measure);

} // namespace aurorawall::cluster
