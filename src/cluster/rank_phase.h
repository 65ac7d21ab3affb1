#pragma once
// What a rank is doing, as its heartbeat tells the master (cluster/watchdog.h), so that the master can
// say where a rank fell silent.
#include <cstdint>
#include <string>

namespace aurorawall::cluster {

enum class RankPhase : std::int64_t {
    SetUp = 0,  // context, shaders, precomputed tables
    Broadcast,  // waiting for the master's message of the next frame
    Draw,       // drawing its bands and exchanging those drawn for other ranks' screens
    Gather,     // sending its report (and, for a screenshot or movie frame, its screens) to the master
    Output,     // reading back and writing the outputs after the last frame
    Finished,   // left the run; silence from now on is expected
};

// "set-up", "drawing frame 12", "the gather of frame 12", ... (`frame`: the last frame it was given).
std::string describePhase(RankPhase phase, std::uint64_t frame);

} // namespace aurorawall::cluster
