#pragma once
// The master's TCP listener for the wall's text protocol (docs/driving.md): one command per line,
// one answer line per command. It never blocks and has no thread: the frame loop calls poll() once
// per frame, which accepts new clients, reads what has arrived and hands out complete lines, at most
// a given number per call; lines beyond that wait in the client's queue and, while a client has
// kMaxQueuedLines waiting, its socket is not read, so a flood is held back by TCP itself.
// A client may disconnect at any time: its unfinished line is dropped, its complete lines are still
// carried out. IPv4; POSIX sockets.
#include <cstddef>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace aurorawall::control {

struct ControlLine {
    std::uint64_t client = 0; // who sent it, for the answer
    std::string text;         // without the newline
};

class ControlServer {
public:
    static constexpr std::size_t kMaxLineBytes = 1024;   // a longer line is answered with an error, then the client closed
    static constexpr std::size_t kMaxQueuedLines = 64;   // per client
    static constexpr std::size_t kMaxClients = 16;       // more are told so and closed
    static constexpr std::size_t kMaxPendingAnswerBytes = 1 << 20; // a client that reads nothing is closed

    // Listens on bindAddress (dotted IPv4) at port (0: a free port the system picks). Throws
    // InputError naming --control-bind or --control-port if it cannot.
    ControlServer(const std::string& bindAddress, int port);
    ~ControlServer();
    ControlServer(const ControlServer&) = delete;
    ControlServer& operator=(const ControlServer&) = delete;

    int port() const { return port_; }
    const std::string& address() const { return address_; }

    // Accepts, reads and sends what it can without waiting; returns up to maxLines complete lines,
    // taken in turn from the clients.
    std::vector<ControlLine> poll(std::size_t maxLines);
    // Sends one answer line (the newline is added) to a client; nothing if it has gone.
    void answer(std::uint64_t client, const std::string& text);

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
    };
    void accept();
    void read(Client& c);
    void flush(Client& c);
    void closeFinished();

    int listenFd_ = -1;
    int port_ = 0;
    std::string address_;
    std::uint64_t nextClient_ = 1;
    std::map<std::uint64_t, Client> clients_;
};

} // namespace aurorawall::control
