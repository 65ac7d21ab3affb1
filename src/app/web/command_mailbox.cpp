#include "app/web/command_mailbox.h"

#include <algorithm>
#include <chrono>

namespace aurorawall::app::web {

std::optional<std::string> CommandMailbox::ask(const std::string& line, double timeoutS)
{
    std::unique_lock<std::mutex> lock(mutex_);
    if (closed_)
        return std::nullopt;
    const std::uint64_t id = next_++;
    waiting_.push_back({id, line});
    answers_[id] = std::nullopt;
    answered_.wait_for(lock, std::chrono::duration<double>(timeoutS),
                       [&] { return closed_ || answers_[id].has_value(); });
    std::optional<std::string> answer = std::move(answers_[id]);
    answers_.erase(id);
    waiting_.erase(std::remove_if(waiting_.begin(), waiting_.end(),
                                  [id](const control::ControlLine& l) { return l.client == id; }),
                   waiting_.end());
    return answer;
}

void CommandMailbox::close()
{
    std::lock_guard<std::mutex> lock(mutex_);
    closed_ = true;
    waiting_.clear();
    answered_.notify_all();
}

std::vector<control::ControlLine> CommandMailbox::poll(std::size_t maxLines)
{
    std::lock_guard<std::mutex> lock(mutex_);
    std::vector<control::ControlLine> lines;
    while (!waiting_.empty() && lines.size() < maxLines) {
        lines.push_back(std::move(waiting_.front()));
        waiting_.pop_front();
    }
    return lines;
}

void CommandMailbox::answer(std::uint64_t client, const std::string& text)
{
    std::lock_guard<std::mutex> lock(mutex_);
    const auto it = answers_.find(client);
    if (it == answers_.end())
        return; // the asker gave up waiting
    it->second = text;
    answered_.notify_all();
}

} // namespace aurorawall::app::web
