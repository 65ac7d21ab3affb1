#include "app/control/control_server.h"

#include "common/input_error.h"

#include <arpa/inet.h>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <fstream>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <poll.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <unistd.h>
#include <utility>

namespace aurorawall::app::control {

namespace {

void setNonBlocking(int fd)
{
    const int flags = ::fcntl(fd, F_GETFL, 0);
    ::fcntl(fd, F_SETFL, flags | O_NONBLOCK);
}

} // namespace

namespace {

double secondsNow()
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

} // namespace

std::string readControlToken(const std::string& file)
{
    if (file.empty())
        return "";
    struct stat status{};
    if (::stat(file.c_str(), &status) != 0)
        throw common::inputError(file, 0, std::string("--control-token-file: cannot read it: ") + std::strerror(errno));
    if (!S_ISREG(status.st_mode))
        throw common::inputError(file, 0, "--control-token-file: not a regular file");
    if (status.st_mode & (S_IRWXG | S_IRWXO))
        throw common::inputError(file, 0, "--control-token-file: others than its owner may read or write it (chmod 600)");
    std::ifstream in(file);
    std::string token;
    if (!in || !std::getline(in, token))
        throw common::inputError(file, 0, "--control-token-file: cannot read its first line");
    while (!token.empty() && (token.back() == '\r' || token.back() == ' ' || token.back() == '\t'))
        token.pop_back();
    if (token.empty())
        throw common::inputError(file, 1, "--control-token-file: the first line (the secret) is empty");
    if (token.size() > kMaxTokenBytes)
        throw common::inputError(file, 1, "--control-token-file: the secret is " + std::to_string(token.size()) +
                                              " bytes long, more than " + std::to_string(kMaxTokenBytes));
    return token;
}

in_addr bindAddressOf(const std::string& bindAddress)
{
    in_addr address{};
    if (::inet_pton(AF_INET, bindAddress.c_str(), &address) != 1)
        throw common::UsageError("--control-bind " + bindAddress + ": not an IPv4 address (e.g. 127.0.0.1 or 0.0.0.0)");
    return address;
}

ControlServer::ControlServer(const std::string& bindAddress, int port, std::string token, double idleTimeoutS,
                             double linesPerSecond)
    : address_(bindAddress), token_(std::move(token)), idleTimeoutS_(idleTimeoutS), linesPerSecond_(linesPerSecond)
{
    sockaddr_in addr{};
    addr.sin_family = AF_INET;
    addr.sin_port = htons(static_cast<std::uint16_t>(port));
    addr.sin_addr = bindAddressOf(bindAddress);
    listenFd_ = ::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
    const int on = 1;
    if (listenFd_ < 0 || ::setsockopt(listenFd_, SOL_SOCKET, SO_REUSEADDR, &on, sizeof on) != 0 ||
        ::bind(listenFd_, reinterpret_cast<sockaddr*>(&addr), sizeof addr) != 0 || ::listen(listenFd_, 16) != 0) {
        const std::string reason = std::strerror(errno);
        if (listenFd_ >= 0)
            ::close(listenFd_);
        throw common::InputError("--control-port " + std::to_string(port) + ": cannot listen on " + bindAddress + ":" +
                         std::to_string(port) + ": " + reason);
    }
    setNonBlocking(listenFd_);
    socklen_t size = sizeof addr;
    ::getsockname(listenFd_, reinterpret_cast<sockaddr*>(&addr), &size);
    port_ = ntohs(addr.sin_port);
}

ControlServer::~ControlServer()
{
    for (auto& [id, c] : clients_) {
        flush(c); // the last answers ("ok quit"), as far as the socket takes them now
        ::close(c.fd);
    }
    ::close(listenFd_);
}

void ControlServer::accept()
{
    while (true) {
        const int fd = ::accept4(listenFd_, nullptr, nullptr, SOCK_NONBLOCK | SOCK_CLOEXEC);
        if (fd < 0)
            return; // EAGAIN: none left (or a client that gave up before being accepted)
        if (clients_.size() >= kMaxClients) {
            // The operator is never locked out: the longest idle client makes room.
            auto idlest = clients_.begin();
            for (auto it = clients_.begin(); it != clients_.end(); ++it)
                if (it->second.lastHeardS < idlest->second.lastHeardS)
                    idlest = it;
            const std::string bye = "error closing this connection, the longest idle of " +
                                    std::to_string(kMaxClients) + ", to admit a new client\n";
            ::send(idlest->second.fd, bye.data(), bye.size(), MSG_NOSIGNAL);
            ::close(idlest->second.fd);
            clients_.erase(idlest);
        }
        // Each answer leaves at once: held back by Nagle's algorithm, the last line before a close
        // (an error saying why) would be lost to the reset that closing on unread input sends.
        const int on = 1;
        ::setsockopt(fd, IPPROTO_TCP, TCP_NODELAY, &on, sizeof on);
        Client& c = clients_[nextClient_++];
        c.fd = fd;
        c.authenticated = token_.empty();
        c.lastHeardS = secondsNow();
        c.rate = TokenBucket(linesPerSecond_, linesPerSecond_, c.lastHeardS);
    }
}

void ControlServer::read(Client& c)
{
    if (c.overRate)
        return; // also when it hangs up: it is closed once its lines are answered
    // One read per client per poll: the bytes a flood can bring in one frame are bounded.
    char buffer[4096];
    const ssize_t n = ::recv(c.fd, buffer, sizeof buffer, 0);
    if (n == 0) {
        c.readClosed = true;
        c.partial.clear(); // a line cut off by the disconnection is not a command
        return;
    }
    if (n < 0) {
        if (errno != EAGAIN && errno != EWOULDBLOCK && errno != EINTR)
            c.failed = true;
        return;
    }
    c.lastHeardS = secondsNow();
    for (ssize_t i = 0; i < n; ++i) {
        if (buffer[i] == '\n') {
            received(c, std::move(c.partial));
            c.partial.clear();
            if (c.failed || c.overRate)
                return; // the rest of the bytes are dropped: nothing more is read from it
        } else if (c.partial.size() >= kMaxLineBytes &&
                   !(buffer[i] == '\r' && c.partial.size() == kMaxLineBytes)) { // a CR before the LF ends the line too
            c.outgoing += "error line longer than " + std::to_string(kMaxLineBytes) + " bytes; closing\n";
            flush(c);
            c.failed = true;
            return;
        } else {
            c.partial += buffer[i];
        }
    }
}

void ControlServer::received(Client& c, std::string line)
{
    if (!c.rate.take(c.lastHeardS)) {
        c.overRate = true;
        return;
    }
    if (c.authenticated) {
        c.lines.push_back(std::move(line));
        return;
    }
    if (!line.empty() && line.back() == '\r')
        line.pop_back();
    if (line == "auth " + token_) {
        c.authenticated = true;
        c.outgoing += "ok auth\n";
    } else {
        c.outgoing += "error authentication required: the first line must be auth TOKEN; closing\n";
        c.failed = true;
    }
    flush(c);
}

void ControlServer::flush(Client& c)
{
    while (!c.outgoing.empty()) {
        const ssize_t n = ::send(c.fd, c.outgoing.data(), c.outgoing.size(), MSG_NOSIGNAL);
        if (n < 0) {
            if (errno != EAGAIN && errno != EWOULDBLOCK && errno != EINTR)
                c.failed = true;
            return;
        }
        c.outgoing.erase(0, static_cast<size_t>(n));
    }
}

void ControlServer::closeFinished()
{
    const double now = secondsNow();
    for (auto it = clients_.begin(); it != clients_.end();) {
        Client& c = it->second;
        if (!c.failed && c.overRate && c.awaiting == 0 && c.lines.empty()) {
            char rate[32];
            std::snprintf(rate, sizeof rate, "%g", linesPerSecond_);
            c.outgoing += std::string("error more than ") + rate + " lines per second; closing\n";
            flush(c);
            c.failed = true;
        }
        if (!c.failed && c.awaiting == 0 && c.lines.empty() && now - c.lastHeardS > idleTimeoutS_) {
            char seconds[32];
            std::snprintf(seconds, sizeof seconds, "%g", idleTimeoutS_);
            c.outgoing += std::string("error closing this connection: idle for more than ") + seconds + " s\n";
            flush(c);
            c.failed = true;
        }
        const bool done = c.readClosed && c.lines.empty() && c.awaiting == 0 && c.outgoing.empty();
        if (c.failed || done) {
            ::close(c.fd);
            it = clients_.erase(it);
        } else {
            ++it;
        }
    }
}

std::vector<ControlLine> ControlServer::poll(std::size_t maxLines)
{
    std::vector<pollfd> fds{{listenFd_, POLLIN, 0}};
    std::vector<std::uint64_t> ids{0};
    for (auto& [id, c] : clients_) {
        short events = 0;
        if (!c.readClosed && !c.overRate && c.lines.size() < kMaxQueuedLines)
            events |= POLLIN;
        if (!c.outgoing.empty())
            events |= POLLOUT;
        fds.push_back({c.fd, events, 0});
        ids.push_back(id);
    }
    if (::poll(fds.data(), fds.size(), 0) > 0) {
        for (size_t i = 1; i < fds.size(); ++i) {
            Client& c = clients_.at(ids[i]);
            if (fds[i].revents & (POLLIN | POLLHUP | POLLERR))
                read(c);
            if (fds[i].revents & POLLOUT)
                flush(c);
        }
        if (fds[0].revents & POLLIN)
            accept();
    }
    // Hand out lines one per client per round, so that a flooding client cannot starve the others.
    std::vector<ControlLine> lines;
    for (bool any = true; any && lines.size() < maxLines;) {
        any = false;
        for (auto& [id, c] : clients_) {
            if (lines.size() >= maxLines)
                break;
            if (!c.failed && !c.lines.empty()) {
                lines.push_back({id, std::move(c.lines.front())});
                c.lines.erase(c.lines.begin());
                ++c.awaiting;
                any = true;
            }
        }
    }
    closeFinished();
    return lines;
}

void ControlServer::answer(std::uint64_t client, const std::string& text)
{
    const auto it = clients_.find(client);
    if (it == clients_.end())
        return;
    Client& c = it->second;
    if (c.awaiting > 0)
        --c.awaiting;
    c.outgoing += text + "\n";
    if (c.outgoing.size() > kMaxPendingAnswerBytes)
        c.failed = true;
    flush(c);
}

} // namespace aurorawall::app::control
