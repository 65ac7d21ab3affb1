#include "cluster/frame_message.h"

#include "cluster/message_bytes.h"

#include <stdexcept>
#include <string>

namespace aurorawall::cluster {

std::size_t frameMessageBytes(std::size_t bandCount)
{
    return sizeof(FrameState) + 2 * sizeof(std::int32_t) + bandCount * sizeof(std::int32_t) +
           kMaxInputEvents * sizeof(InputEvent);
}

std::vector<char> packFrameMessage(const FrameMessage& message, std::size_t bandCount)
{
    if (message.assignment.size() != bandCount)
        throw std::invalid_argument("frame message: an assignment of " + std::to_string(message.assignment.size()) +
                                    " bands for " + std::to_string(bandCount) + " bands");
    if (message.events.size() > kMaxInputEvents)
        throw std::invalid_argument("frame message: " + std::to_string(message.events.size()) +
                                    " input events, at most " + std::to_string(kMaxInputEvents));
    ByteWriter out;
    out.put(message.state);
    out.put(static_cast<std::int32_t>(bandCount));
    out.put(static_cast<std::int32_t>(message.events.size()));
    for (std::int32_t rank : message.assignment)
        out.put(rank);
    for (const InputEvent& event : message.events)
        out.put(event);
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
    if (bands < 0 || static_cast<std::size_t>(bands) != bandCount || events < 0 ||
        static_cast<std::size_t>(events) > kMaxInputEvents)
        throw std::runtime_error("frame message: " + std::to_string(bands) + " bands and " + std::to_string(events) +
                                 " events, expected " + std::to_string(bandCount) + " bands and at most " +
                                 std::to_string(kMaxInputEvents) + " events");
    message.assignment.resize(bandCount);
    for (std::int32_t& rank : message.assignment)
        rank = in.get<std::int32_t>();
    message.events.resize(static_cast<std::size_t>(events));
    for (InputEvent& event : message.events)
        event = in.get<InputEvent>();
    return message;
}

} // namespace aurorawall::cluster
