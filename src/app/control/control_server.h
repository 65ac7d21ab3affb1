#pragma once
// The master's TCP listener for the wall's text protocol (docs/driving.md): one command per line,
// one answer line per command. It never blocks and has no thread: the frame loop calls poll() once
// per frame, which accepts new clients, reads what has arrived and hands out complete lines, at most
// a given number per call; lines beyond that wait in the client's queue and, while a client has
// kMaxQueuedLines waiting, its socket is not read, so a flood is held back by TCP itself.
// A client may disconnect at any time: its unfinished line is dropped, its complete lines are still
// carried out. IPv4; POSIX sockets.
// The operator is never locked out: when kMaxClients are connected, a new connection closes the
// longest idle client (which gets one line saying so); a client that sends nothing for the idle
// timeout (kIdleTimeoutS, 10 minutes) while nothing of its is pending is closed with one line; one
// whose answers back up past kMaxPendingAnswerBytes (it never reads) is dropped.
// Each client may send kMaxLinesPerSecond lines per second, as many at once (a token bucket): a line
// beyond that ends the client's reading; its lines within the limit are still carried out and
// answered, then it gets one error line and is closed. So a flood costs the frame loop at most one
// second's worth of lines per connection, and its client learns at once why it was cut off.
// With a token (a shared secret; required by the render command for any address but loopback),
// a client's first line must be "auth TOKEN": it is answered "ok auth" and the client's later lines
// are handed out; any other first line gets one error line and the client is closed, before any of
// its lines reaches the wall.
#include "app/control/token_bucket.h"
#include "app/control/command_channel.h"

#include <cstddef>
#include <netinet/in.h>

#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace aurorawall::app::control {

// The shared secret in the first line of `file` (empty for an empty file name: no token). Throws
// InputError naming the file if it cannot be read, is readable or writable by anyone but its owner,
// or its first line is empty or longer than kMaxTokenBytes.
std::string readControlToken(const std::string& file);

// The longest secret: "auth SECRET" must fit a control line (ControlServer::kMaxLineBytes).
constexpr std::size_t kMaxTokenBytes = 512;

// The IPv4 address --control-bind names (dotted quad), for the control port and the web console alike.
// Throws UsageError naming the option otherwise.
in_addr bindAddressOf(const std::string& bindAddress);

class ControlServer : public CommandChannel {
public:
    static constexpr std::size_t kMaxLineBytes = 1024;   // a longer line is answered with an error, then the client closed
    static constexpr std::size_t kMaxQueuedLines = 64;   // per client
    static constexpr std::size_t kMaxClients = 16;       // a 17th closes the longest idle one (told so)
    static constexpr double kIdleTimeoutS = 600.0;       // a client silent this long is told so and closed
    static constexpr std::size_t kMaxPendingAnswerBytes = 1 << 20; // a client that reads nothing is closed
    static constexpr double kMaxLinesPerSecond = 100.0;  // per client, and as many at once; more: closed

    // Listens on bindAddress (dotted IPv4) at port (0: a free port the system picks); with a
    // non-empty token, clients authenticate first (above). Throws InputError naming --control-bind
    // or --control-port if it cannot.
    ControlServer(const std::string& bindAddress, int port, std::string token = "",
                  double idleTimeoutS = kIdleTimeoutS, double linesPerSecond = kMaxLinesPerSecond);
    ~ControlServer() override;
    ControlServer(const ControlServer&) = delete;
    ControlServer& operator=(const ControlServer&) = delete;

    int port() const { return port_; }
    const std::string& address() const { return address_; }

    // Accepts, reads and sends what it can without waiting; returns up to maxLines complete lines,
    // taken in turn from the clients.
    std::vector<ControlLine> poll(std::size_t maxLines) override;
    // Sends one answer line (the newline is added) to a client; nothing if it has gone.
    void answer(std::uint64_t client, const std::string& text) override;

    std::size_t clientCount() const { return clients_.size(); }

private:
    struct Client {
        int fd = -1;
        std::string partial;           // bytes after the last newline
        std::vector<std::string> lines; // complete, not yet handed out
        std::string outgoing;          // answers not yet sent
        std::size_t awaiting = 0;      // lines handed out, not yet answered
        bool readClosed = false;       // the client sent end-of-file
        bool failed = false;           // the connection is broken or the client misbehaved
        bool authenticated = false;    // its first line was "auth TOKEN" (or no token is asked)
        double lastHeardS = 0.0;       // when it last sent bytes (steady clock, s)
        TokenBucket rate;              // its lines per second
        bool overRate = false;         // it passed the rate: read no more, close once its lines are answered
    };
    // A complete line from the client: queued, or, before it has authenticated, checked as its
    // "auth TOKEN" line.
    void received(Client& c, std::string line);
    void accept();
    void read(Client& c);
    void flush(Client& c);
    void closeFinished();

    int listenFd_ = -1;
    int port_ = 0;
    std::string address_;
    std::string token_;
    double idleTimeoutS_;
    double linesPerSecond_;
    std::uint64_t nextClient_ = 1;
    std::map<std::uint64_t, Client> clients_;
};

} // namespace aurorawall::app::control
