#pragma once
// Where the wall's command lines come from and where their answers go: the control port's TCP
// clients (control_server.h) and the browser console's requests (app/web) are both channels, so
// that serveCommands (remote_control.h) carries out the lines of either in the same way.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace aurorawall::app::control {

struct ControlLine {
    std::uint64_t client = 0; // who sent it, for the answer
    std::string text;         // without the newline
};

class CommandChannel {
public:
    virtual ~CommandChannel() = default;
    // Up to maxLines complete lines that have arrived; never waits.
    virtual std::vector<ControlLine> poll(std::size_t maxLines) = 0;
    // One answer line (without its newline) to the client that sent a line; nothing if it has gone.
    virtual void answer(std::uint64_t client, const std::string& text) = 0;
};

// Several channels as one: each poll takes from every channel in turn (maxLines shared out, at least
// one each), and the client numbers it hands out name the channel too, so that an answer given later
// (a screenshot, a preset) finds its way back.
class ChannelSet : public CommandChannel {
public:
    void add(CommandChannel& channel) { channels_.push_back(&channel); }
    bool empty() const { return channels_.empty(); }
    std::vector<ControlLine> poll(std::size_t maxLines) override;
    void answer(std::uint64_t client, const std::string& text) override;

private:
    std::vector<CommandChannel*> channels_;
};

} // namespace aurorawall::app::control
