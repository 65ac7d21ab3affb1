#include "app/control/command_channel.h"

#include <algorithm>

namespace aurorawall::app::control {

// A client number c of channel i travels as c * n + i (n channels, fixed once the frames run).

std::vector<ControlLine> ChannelSet::poll(std::size_t maxLines)
{
    std::vector<ControlLine> lines;
    const std::size_t n = channels_.size();
    const std::size_t share = std::max<std::size_t>(1, maxLines / std::max<std::size_t>(1, n));
    for (std::size_t i = 0; i < n; ++i)
        for (ControlLine& line : channels_[i]->poll(share)) {
            line.client = line.client * n + i;
            lines.push_back(std::move(line));
        }
    return lines;
}

void ChannelSet::answer(std::uint64_t client, const std::string& text)
{
    const std::size_t n = channels_.size();
    if (n > 0)
        channels_[client % n]->answer(client / n, text);
}

} // namespace aurorawall::app::control
