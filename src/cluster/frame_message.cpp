#include "cluster/frame_message.h"

#include "cluster/message_bytes.h"

#include <algorithm>
#include <array>
#include <stdexcept>
#include <string>

namespace aurorawall::cluster {

std::size_t frameMessageBytes(std::size_t bandCount)
{
    return sizeof(FrameState) + 3 * sizeof(std::int32_t) + bandCount * sizeof(std::int32_t) +
           kMaxInputEvents * sizeof(InputEvent) + kHudLines * kHudColumns;
}

std::vector<char> packFrameMessage(const FrameMessage& message, std::size_t bandCount)
{
    if (message.assignment.size() != bandCount)
        throw std::invalid_argument("frame message: an assignment of " + std::to_string(message.assignment.size()) +
                                    " bands for " + std::to_string(bandCount) + " bands");
    if (message.events.size() > kMaxInputEvents)
        throw std::invalid_argument("frame message: " + std::to_string(message.events.size()) +
                                    " input events, at most " + std::to_string(kMaxInputEvents));
    if (message.hud.size() > kHudLines)
        throw std::invalid_argument("frame message: " + std::to_string(message.hud.size()) + " HUD lines, at most " +
                                    std::to_string(kHudLines));
    for (const std::string& line : message.hud)
        if (line.size() > kHudColumns)
            throw std::invalid_argument("frame message: the HUD line '" + line + "' is longer than " +
                                        std::to_string(kHudColumns) + " characters");
    ByteWriter out;
    out.put(message.state);
    out.put(static_cast<std::int32_t>(bandCount));
    out.put(static_cast<std::int32_t>(message.events.size()));
    out.put(static_cast<std::int32_t>(message.hud.size()));
    for (std::int32_t rank : message.assignment)
        out.put(rank);
    for (size_t i = 0; i < kMaxInputEvents; ++i)
        out.put(i < message.events.size() ? message.events[i] : InputEvent{});
    for (const std::string& line : message.hud) {
        std::array<char, kHudColumns> text{};
        line.copy(text.data(), line.size());
        out.put(text);
    }
    return out.padded(frameMessageBytes(bandCount));
}

FrameMessage unpackFrameMessage(const std::vector<char>& bytes, std::size_t bandCount)
{
    if (bytes.size() != frameMessageBytes(bandCount))
        throw std::runtime_error("frame message: " + std::to_string(bytes.size()) + " bytes, expected " +
                                 std::to_string(frameMessageBytes(bandCount)));
    ByteReader in(bytes.data(), bytes.size(), "frame message");
    FrameMessage message;
    message.state = in.get<FrameState>();
    const auto bands = in.get<std::int32_t>();
    const auto events = in.get<std::int32_t>();
    const auto hudLines = in.get<std::int32_t>();
    if (bands < 0 || static_cast<std::size_t>(bands) != bandCount || events < 0 ||
        static_cast<std::size_t>(events) > kMaxInputEvents || hudLines < 0 ||
        static_cast<std::size_t>(hudLines) > kHudLines)
        throw std::runtime_error("frame message: " + std::to_string(bands) + " bands, " + std::to_string(events) +
                                 " events and " + std::to_string(hudLines) + " HUD lines, expected " +
                                 std::to_string(bandCount) + " bands, at most " + std::to_string(kMaxInputEvents) +
                                 " events and " + std::to_string(kHudLines) + " HUD lines");
    message.assignment.resize(bandCount);
    for (std::int32_t& rank : message.assignment)
        rank = in.get<std::int32_t>();
    for (size_t i = 0; i < kMaxInputEvents; ++i) {
        const auto event = in.get<InputEvent>();
        if (i < static_cast<std::size_t>(events))
            message.events.push_back(event);
    }
    for (std::int32_t i = 0; i < hudLines; ++i) {
        const auto text = in.get<std::array<char, kHudColumns>>();
        message.hud.emplace_back(text.data(), std::find(text.begin(), text.end(), '\0') - text.begin());
    }
    return message;
}

} // namespace aurorawall::cluster
