#pragma once
// What the master sends every rank once per frame, in one broadcast: the FrameState, which rank draws
// each band (cluster/load_balancer.h), the input events every rank must react to alike, and the
// heads-up display's text (app/hud.h), so that every window shows the same HUD. The
// message has the same size every frame for a given band count, so the broadcast needs no size first.
#include "cluster/frame_state.h"

#include <cstdint>
#include <string>
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
constexpr std::size_t kHudLines = 24, kHudColumns = 40; // the HUD's room in the message

struct FrameMessage {
    FrameState state;
    std::vector<std::int32_t> assignment; // assignment[band]: the rank that draws it this frame
    std::vector<InputEvent> events;       // at most kMaxInputEvents
    std::vector<std::string> hud;         // the HUD's lines, none when it is hidden: at most kHudLines
                                          // of at most kHudColumns characters
};

// The size of every frame's message for `bandCount` bands.
std::size_t frameMessageBytes(std::size_t bandCount);

// The message as bytes of frameMessageBytes(bandCount): the state, the band count, the event count,
// the HUD's line count, the assignment, the events (zeros after the last), the HUD's lines (kHudColumns
// bytes each, zeros after the text and after the last line). Throws std::invalid_argument if the
// assignment does not hold bandCount bands, there are more than kMaxInputEvents events, more than
// kHudLines HUD lines or a longer one.
std::vector<char> packFrameMessage(const FrameMessage& message, std::size_t bandCount);

// Throws std::runtime_error if the bytes are not a message of bandCount bands.
FrameMessage unpackFrameMessage(const std::vector<char>& bytes, std::size_t bandCount);

} // namespace aurorawall::cluster
