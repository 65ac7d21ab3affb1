#pragma once
// The browser console's command lines on their way to the frame loop: a web server thread asks
// (and waits), the frame loop takes the lines once a frame like the control port's (it is a
// CommandChannel) and answers them. Thread-safe; the frame loop never waits on it.
#include "app/control/command_channel.h"

#include <condition_variable>
#include <cstdint>
#include <deque>
#include <map>
#include <mutex>
#include <optional>
#include <string>

namespace aurorawall::app::web {

class CommandMailbox : public control::CommandChannel {
public:
    // From any thread but the frame loop's: hands `line` over and waits for its answer, at most
    // timeoutS seconds. Nothing if none came in time (a line not yet taken is then withdrawn, not
    // carried out later) or once the mailbox is closed.
    std::optional<std::string> ask(const std::string& line, double timeoutS);
    // Every ask, waiting or to come, returns nothing at once (the wall is stopping).
    void close();

    std::vector<control::ControlLine> poll(std::size_t maxLines) override;
    void answer(std::uint64_t client, const std::string& text) override;

private:
    std::mutex mutex_;
    std::condition_variable answered_;
    std::deque<control::ControlLine> waiting_;                // asked, not yet taken by the frame loop
    std::map<std::uint64_t, std::optional<std::string>> answers_; // an asker still waits for each
    std::uint64_t next_ = 1;
    bool closed_ = false;
};

} // namespace aurorawall::app::web
