#pragma once
// What the master sends every rank once per frame, in one broadcast: the FrameState, which rank draws
// each band (cluster/load_balancer.h), and the input events every rank must react to alike. The
// message has the same size every frame for a given band count, so the broadcast needs no size first.
#include "cluster/frame_state.h"

#include <cstdint>
#include <vector>

namespace aurorawall::cluster {

// An input event of a window (a key or a pointer, gl::InputEvent). Ranks send theirs to the master
// in their RankMessage (app/navigation flies the camera with them); the frame message keeps room for
// kMaxInputEvents of them per frame that every rank would react to alike, unused so far.
struct InputEvent {
    std::int32_t type = 0; // what happened
    std::int32_t code = 0; // which key or button
    double x = 0.0, y = 0.0; // a drag: the pointer's movement, window pixels
};

constexpr std::size_t kMaxInputEvents = 32;

struct FrameMessage {
    FrameState state;
    std::vector<std::int32_t> assignment; // assignment[band]: the rank that draws it this frame
    std::vector<InputEvent> events;       // at most kMaxInputEvents
};

// The size of every frame's message for `bandCount` bands.
std::size_t frameMessageBytes(std::size_t bandCount);

// The message as bytes of frameMessageBytes(bandCount): the state, the band count, the event count,
// the assignment, the events (zeros after the last). Throws std::invalid_argument if the assignment
// does not hold bandCount bands or there are more than kMaxInputEvents events.
std::vector<char> packFrameMessage(const FrameMessage& message, std::size_t bandCount);

// Throws std::runtime_error if the bytes are not a message of bandCount bands.
FrameMessage unpackFrameMessage(const std::vector<char>& bytes, std::size_t bandCount);

} // namespace aurorawall::cluster
