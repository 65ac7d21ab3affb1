#include "cluster/rank_message.h"

#include "cluster/message_bytes.h"

#include <limits>
#include <stdexcept>
#include <string>

namespace aurorawall::cluster {

namespace {
// A band cost's and an input event's fields without the structs' padding.
constexpr std::size_t kBandCostBytes = sizeof(std::int32_t) + 2 * sizeof(double);
constexpr std::size_t kInputEventBytes = 2 * sizeof(std::int32_t) + 2 * sizeof(double);
} // namespace

std::size_t rankMessageBytes(std::size_t bandCount)
{
    return sizeof(RankReport) + 2 * sizeof(std::int32_t) + bandCount * kBandCostBytes +
           kMaxInputEvents * kInputEventBytes;
}

std::vector<char> packRankMessage(const RankMessage& message, std::size_t bandCount)
{
    if (message.costs.size() > bandCount)
        throw std::invalid_argument("rank message: " + std::to_string(message.costs.size()) + " band costs for " +
                                    std::to_string(bandCount) + " bands");
    if (message.events.size() > kMaxInputEvents)
        throw std::invalid_argument("rank message: " + std::to_string(message.events.size()) +
                                    " input events, at most " + std::to_string(kMaxInputEvents));
    ByteWriter out;
    out.put(message.report);
    out.put(static_cast<std::int32_t>(message.costs.size()));
    out.put(static_cast<std::int32_t>(message.events.size()));
    for (const BandCost& cost : message.costs) {
        out.put(cost.band);
        out.put(cost.cpuMs);
        out.put(cost.work);
    }
    for (const InputEvent& event : message.events) {
        out.put(event.type);
        out.put(event.code);
        out.put(event.x);
        out.put(event.y);
    }
    return out.padded(rankMessageBytes(bandCount));
}

RankMessage unpackRankMessage(const char* bytes, std::size_t bandCount)
{
    ByteReader in(bytes, rankMessageBytes(bandCount), "rank message");
    RankMessage message;
    message.report = in.get<RankReport>();
    const auto count = in.get<std::int32_t>();
    if (count < 0 || static_cast<std::size_t>(count) > bandCount)
        throw std::runtime_error("rank message: " + std::to_string(count) + " band costs for " +
                                 std::to_string(bandCount) + " bands");
    const auto eventCount = in.get<std::int32_t>();
    if (eventCount < 0 || static_cast<std::size_t>(eventCount) > kMaxInputEvents)
        throw std::runtime_error("rank message: " + std::to_string(eventCount) + " input events, at most " +
                                 std::to_string(kMaxInputEvents));
    message.costs.resize(static_cast<std::size_t>(count));
    for (BandCost& cost : message.costs) {
        cost.band = in.get<std::int32_t>();
        cost.cpuMs = in.get<double>();
        cost.work = in.get<double>();
        if (cost.band < 0 || static_cast<std::size_t>(cost.band) >= bandCount)
            throw std::runtime_error("rank message: band " + std::to_string(cost.band) + " of " +
                                     std::to_string(bandCount));
    }
    message.events.resize(static_cast<std::size_t>(eventCount));
    for (InputEvent& event : message.events) {
        event.type = in.get<std::int32_t>();
        event.code = in.get<std::int32_t>();
        event.x = in.get<double>();
        event.y = in.get<double>();
    }
    return message;
}

std::vector<RankMessage> unpackRankMessages(const std::vector<char>& bytes, std::size_t bandCount)
{
    const std::size_t size = rankMessageBytes(bandCount);
    if (bytes.size() % size != 0)
        throw std::runtime_error("rank messages: " + std::to_string(bytes.size()) + " bytes are not a whole number of " +
                                 std::to_string(size) + "-byte messages");
    std::vector<RankMessage> messages;
    for (std::size_t at = 0; at < bytes.size(); at += size)
        messages.push_back(unpackRankMessage(bytes.data() + at, bandCount));
    return messages;
}

std::vector<double> bandCosts(const std::vector<RankMessage>& messages, std::size_t bandCount, BandMeasure measure)
{
    std::vector<double> cost(bandCount, std::numeric_limits<double>::quiet_NaN());
    for (const RankMessage& message : messages)
        for (const BandCost& c : message.costs)
            cost[static_cast<std::size_t>(c.band)] = measure == BandMeasure::Work ? c.work : c.cpuMs;
    return cost;
}

} // namespace aurorawall::cluster
