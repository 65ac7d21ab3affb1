#pragma once
// What a rank is doing, as its heartbeat tells the master (cluster/watchdog.h), so that the master can
// say where a rank fell silent or hung, and how long its main thread has gone without progress.
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

// The progress of a rank's main thread, kept from the marks it makes (times in seconds on any
// monotonic clock; pure bookkeeping, the caller serialises access). Progress is a change of phase
// or entering or leaving a wait for other ranks (a broadcast, gather, exchange or barrier). A main
// thread that is not waiting and has made no progress for a long time is stuck in its own work,
// e.g. a driver call that does not return.
class MainThreadProgress {
public:
    explicit MainThreadProgress(double startS);

    // Entering Draw of a new frame completes the previous frame: its duration, from the Draw of the
    // frame before, is the frame time.
    void phaseChanged(RankPhase phase, std::uint64_t frame, double nowS);
    void waitBegins(double nowS);
    void waitEnds(double nowS);

    struct Snapshot {
        RankPhase phase = RankPhase::SetUp;
        std::uint64_t frame = 0;
        bool waiting = false;        // inside a wait for other ranks
        double stalledS = 0.0;       // since the last progress, while not waiting (0 while waiting)
        double slowestFrameS = 0.0;  // the longest completed frame (0: none completed yet)
        double busyThisFrameS = 0.0; // time outside waits since this frame's Draw began
    };
    Snapshot at(double nowS) const;

private:
    RankPhase phase_ = RankPhase::SetUp;
    std::uint64_t frame_ = 0;
    bool waiting_ = false;
    double progressS_;         // the last progress
    double frameStartS_ = -1.0; // the last Draw of a new frame (< 0: none yet)
    double slowestFrameS_ = 0.0;
    double busyBeforeS_ = 0.0; // this frame's time outside waits up to the last progress
};

} // namespace aurorawall::cluster
