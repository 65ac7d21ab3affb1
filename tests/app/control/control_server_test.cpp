// The control server on loopback: several clients at once, a line cut off by a disconnection, a
// client that sends and leaves, a flood held to a number of lines per poll and to a rate per client,
// an overlong line, and addresses it cannot listen on.
#include "app/control/control_server.h"

#include "common/input_error.h"

#include <gtest/gtest.h>

#include <arpa/inet.h>
#include <chrono>
#include <netinet/in.h>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <poll.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <thread>
#include <unistd.h>

using namespace aurorawall;
using namespace aurorawall::app::control;

namespace {

// A blocking test client.
class Client {
public:
    explicit Client(int port)
    {
        fd_ = ::socket(AF_INET, SOCK_STREAM, 0);
        sockaddr_in addr{};
        addr.sin_family = AF_INET;
        addr.sin_port = htons(static_cast<std::uint16_t>(port));
        addr.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
        EXPECT_EQ(::connect(fd_, reinterpret_cast<sockaddr*>(&addr), sizeof addr), 0);
    }
    ~Client() { close(); }
    void send(const std::string& bytes) { EXPECT_EQ(::send(fd_, bytes.data(), bytes.size(), MSG_NOSIGNAL), ssize_t(bytes.size())); }
    void close()
    {
        if (fd_ >= 0)
            ::close(fd_);
        fd_ = -1;
    }
    // One line from the server (without the newline), or "" after 5 s.
    std::string readLine()
    {
        std::string line;
        char c;
        pollfd p{fd_, POLLIN, 0};
        while (::poll(&p, 1, 5000) == 1 && ::recv(fd_, &c, 1, 0) == 1) {
            if (c == '\n')
                return line;
            line += c;
        }
        return line;
    }

private:
    int fd_ = -1;
};

// Polls until `count` lines have come or `wait` has passed, as a frame loop would.
std::vector<ControlLine> pollFor(ControlServer& server, size_t count, size_t perPoll = 16,
                                 std::chrono::milliseconds wait = std::chrono::milliseconds(5000))
{
    std::vector<ControlLine> lines;
    const auto end = std::chrono::steady_clock::now() + wait;
    while (lines.size() < count && std::chrono::steady_clock::now() < end) {
        for (ControlLine& l : server.poll(perPoll))
            lines.push_back(std::move(l));
        std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
    return lines;
}

} // namespace

TEST(ControlServer, AnswersSeveralClientsAtOnce)
{
    ControlServer server("127.0.0.1", 0);
    ASSERT_GT(server.port(), 0);
    Client a(server.port()), b(server.port());
    a.send("status\n");
    b.send("pause\r\n");
    const std::vector<ControlLine> lines = pollFor(server, 2);
    ASSERT_EQ(lines.size(), 2u);
    for (const ControlLine& l : lines)
        server.answer(l.client, "ok " + l.text);
    EXPECT_EQ(a.readLine(), "ok status");
    EXPECT_EQ(b.readLine(), "ok pause\r"); // the line as sent; the parser drops the '\r'
}

TEST(ControlServer, ALineCutOffByADisconnectionIsDropped)
{
    ControlServer server("127.0.0.1", 0);
    {
        Client half(server.port());
        half.send("goto 65 2"); // no newline, then gone
    }
    Client whole(server.port());
    whole.send("status\n");
    const std::vector<ControlLine> lines = pollFor(server, 1);
    ASSERT_EQ(lines.size(), 1u);
    EXPECT_EQ(lines[0].text, "status");
    EXPECT_TRUE(pollFor(server, 1, 16, std::chrono::milliseconds(300)).empty());
    // The half client is gone once its end-of-file has been read.
    EXPECT_EQ(server.clientCount(), 1u);
}

TEST(ControlServer, ALineSentJustBeforeLeavingIsCarriedOut)
{
    ControlServer server("127.0.0.1", 0);
    std::uint64_t id = 0;
    {
        Client c(server.port());
        c.send("quit\n");
        c.close();
        const std::vector<ControlLine> lines = pollFor(server, 1);
        ASSERT_EQ(lines.size(), 1u);
        EXPECT_EQ(lines[0].text, "quit");
        id = lines[0].client;
    }
    server.answer(id, "ok quit"); // to a closed socket: no SIGPIPE, no throw
    pollFor(server, 1, 1, std::chrono::milliseconds(300));
    EXPECT_EQ(server.clientCount(), 0u);
}

TEST(ControlServer, AFloodIsHandedOutInBoundedPortionsInOrder)
{
    ControlServer server("127.0.0.1", 0, "", ControlServer::kIdleTimeoutS, 1e6); // no rate limit here
    Client flood(server.port()), other(server.port());
    std::string bytes;
    for (int i = 0; i < 300; ++i)
        bytes += "time " + std::to_string(i) + "\n";
    flood.send(bytes);
    std::vector<ControlLine> all;
    bool otherSent = false, otherServed = false;
    size_t servedAfter = 0; // flood lines handed out before the other client's line
    const auto end = std::chrono::steady_clock::now() + std::chrono::seconds(5);
    while (all.size() < 301 && std::chrono::steady_clock::now() < end) {
        if (!otherSent && all.size() >= 20) {
            other.send("status\n");
            otherSent = true;
        }
        const std::vector<ControlLine> lines = server.poll(16);
        EXPECT_LE(lines.size(), 16u);
        for (const ControlLine& l : lines) {
            server.answer(l.client, "ok");
            if (l.text == "status") {
                otherServed = true;
                servedAfter = all.size();
            } else {
                all.push_back(l);
            }
        }
        if (otherServed && all.size() >= 300)
            break;
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    ASSERT_EQ(all.size(), 300u);
    for (int i = 0; i < 300; ++i)
        EXPECT_EQ(all[i].text, "time " + std::to_string(i));
    // Served within a few polls of its arrival, not after the flood: one line per client per round.
    EXPECT_TRUE(otherServed);
    EXPECT_LT(servedAfter, 200u);
}

TEST(ControlServer, AnOverlongLineIsRefusedAndTheClientClosed)
{
    ControlServer server("127.0.0.1", 0);
    Client c(server.port());
    c.send(std::string(ControlServer::kMaxLineBytes + 10, 'x'));
    EXPECT_TRUE(pollFor(server, 1, 16, std::chrono::milliseconds(300)).empty());
    EXPECT_EQ(c.readLine(), "error line longer than 1024 bytes; closing");
    EXPECT_EQ(server.clientCount(), 0u);
}

// The limit is of the line itself: a CR before its LF (a "\r\n" client) does not count.
TEST(ControlServer, ALineOfTheLongestLengthIsTakenWithEitherEnd)
{
    ControlServer server("127.0.0.1", 0);
    const std::string longest(ControlServer::kMaxLineBytes, 'x');
    Client c(server.port());
    c.send(longest + "\n" + longest + "\r\n");
    const std::vector<ControlLine> lines = pollFor(server, 2);
    ASSERT_EQ(lines.size(), 2u);
    EXPECT_EQ(lines[0].text, longest);
    EXPECT_EQ(lines[1].text, longest + "\r"); // the line as sent; the parser drops the '\r'
    EXPECT_EQ(server.clientCount(), 1u);
    c.send(longest + "x\r\n");
    EXPECT_TRUE(pollFor(server, 1, 16, std::chrono::milliseconds(300)).empty());
    EXPECT_EQ(c.readLine(), "error line longer than 1024 bytes; closing");
}

TEST(ControlServer, RefusesAddressesItCannotListenOn)
{
    EXPECT_THROW(ControlServer("localhost", 0), common::UsageError); // a name, not an IPv4 address
    EXPECT_THROW(ControlServer("::1", 0), common::UsageError);
    ControlServer first("127.0.0.1", 0);
    try {
        ControlServer second("127.0.0.1", first.port());
        FAIL() << "a port in use was accepted";
    } catch (const common::UsageError&) {
        FAIL() << "a port in use is a runtime failure, not a usage error";
    } catch (const common::InputError& e) {
        EXPECT_NE(std::string(e.what()).find("--control-port " + std::to_string(first.port())), std::string::npos)
            << e.what();
    }
}

namespace {

// Polls until the client's line comes back (the server answers auth lines itself).
std::string answerOf(ControlServer& server, Client& client)
{
    std::string line;
    std::thread reader([&] { line = client.readLine(); });
    const auto end = std::chrono::steady_clock::now() + std::chrono::seconds(5);
    while (std::chrono::steady_clock::now() < end) {
        EXPECT_TRUE(server.poll(16).empty());
        std::this_thread::sleep_for(std::chrono::milliseconds(2));
        if (server.clientCount() == 0)
            break;
    }
    reader.join();
    return line;
}

} // namespace

// With a token, a client's first line must be "auth TOKEN": a wrong token or a command first gets
// one error line and the client is closed, and none of its lines reaches the wall; the right token
// is answered "ok auth" and what follows is handed out.
TEST(ControlServer, ClientsAuthenticateFirstWhenAskedTo)
{
    ControlServer server("127.0.0.1", 0, "s3cret");
    for (const char* first : {"status\n", "auth wrong\nstatus\n", "auth s3cret extra\n"}) {
        Client intruder(server.port());
        intruder.send(first);
        EXPECT_EQ(answerOf(server, intruder), "error authentication required: the first line must be auth TOKEN; closing")
            << first;
        EXPECT_EQ(intruder.readLine(), "") << first; // closed
        EXPECT_EQ(server.clientCount(), 0u) << first;
    }
    Client operatorClient(server.port());
    operatorClient.send("auth s3cret\r\nstatus\n");
    const std::vector<ControlLine> lines = pollFor(server, 1);
    ASSERT_EQ(lines.size(), 1u);
    EXPECT_EQ(lines[0].text, "status");
    EXPECT_EQ(operatorClient.readLine(), "ok auth");
}

// The secret's file: readable by its owner only, its first line not empty.
TEST(ControlServer, TokenFileIsCheckedBeforeUse)
{
    char path[] = "/tmp/aw-token-XXXXXX";
    const int fd = ::mkstemp(path);
    ASSERT_GE(fd, 0);
    ::close(fd);
    EXPECT_EQ(readControlToken(""), "");
    EXPECT_THROW(readControlToken(path), common::InputError); // empty
    {
        std::FILE* f = std::fopen(path, "w");
        std::fputs("  tok en  \n second\n", f);
        std::fclose(f);
    }
    ::chmod(path, 0600);
    EXPECT_EQ(readControlToken(path), "  tok en");
    ::chmod(path, 0644);
    try {
        readControlToken(path);
        ADD_FAILURE() << "a file others may read was taken";
    } catch (const common::InputError& e) {
        EXPECT_NE(std::string(e.what()).find("chmod 600"), std::string::npos) << e.what();
    }
    ::unlink(path);
    EXPECT_THROW(readControlToken(path), common::InputError); // gone
    try {
        readControlToken("/tmp");
        ADD_FAILURE() << "a folder was taken";
    } catch (const common::InputError& e) {
        EXPECT_NE(std::string(e.what()).find("--control-token-file: not a regular file"), std::string::npos) << e.what();
    }
}

// The operator is never locked out: with every slot taken by idle clients, a 17th connection gets in
// and is served, and the longest idle client is told why it is closed.
TEST(ControlServer, ANewClientClosesTheLongestIdleOneWhenFull)
{
    ControlServer server("127.0.0.1", 0);
    std::vector<std::unique_ptr<Client>> idle;
    for (std::size_t i = 0; i < ControlServer::kMaxClients; ++i) {
        idle.push_back(std::make_unique<Client>(server.port()));
        for (int k = 0; k < 100 && server.clientCount() < i + 1; ++k) {
            server.poll(16);
            std::this_thread::sleep_for(std::chrono::milliseconds(2));
        }
    }
    ASSERT_EQ(server.clientCount(), ControlServer::kMaxClients);
    Client newcomer(server.port());
    newcomer.send("status\n");
    const std::vector<ControlLine> lines = pollFor(server, 1);
    ASSERT_EQ(lines.size(), 1u);
    EXPECT_EQ(lines[0].text, "status");
    server.answer(lines[0].client, "ok");
    EXPECT_EQ(newcomer.readLine(), "ok");
    EXPECT_EQ(idle.front()->readLine(), "error closing this connection, the longest idle of 16, to admit a new client");
    EXPECT_EQ(server.clientCount(), ControlServer::kMaxClients);
}

// A client that sends nothing for the idle timeout is told so and closed; one that keeps talking is not.
// The talking client speaks every 20 ms against a 1 s timeout, so that only a stall of the whole test
// of 50 times that closes it.
TEST(ControlServer, IdleClientsTimeOut)
{
    ControlServer server("127.0.0.1", 0, "", 1.0);
    Client quiet(server.port()), talking(server.port());
    const auto end = std::chrono::steady_clock::now() + std::chrono::milliseconds(2200);
    while (std::chrono::steady_clock::now() < end) {
        talking.send("status\n");
        for (const ControlLine& l : server.poll(16))
            server.answer(l.client, "ok");
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    EXPECT_EQ(quiet.readLine(), "error closing this connection: idle for more than 1 s");
    EXPECT_EQ(quiet.readLine(), ""); // closed
    EXPECT_EQ(server.clientCount(), 1u);
}

// A client past the rate (here 150 lines at once against 100 per second, as many at once): its first
// 100 lines are carried out and answered in order, then it gets one error line and is closed; the
// 50 beyond are dropped. Another client, within the rate, is served all along.
TEST(ControlServer, AClientPastTheRateIsAnsweredThenClosed)
{
    ControlServer server("127.0.0.1", 0);
    Client flood(server.port()), other(server.port());
    std::string bytes;
    for (int i = 0; i < 150; ++i)
        bytes += "time " + std::to_string(i) + "\n";
    flood.send(bytes);
    other.send("status\n");
    std::vector<std::string> floodLines;
    bool otherServed = false;
    const auto end = std::chrono::steady_clock::now() + std::chrono::seconds(5);
    while (std::chrono::steady_clock::now() < end) {
        if (otherServed && floodLines.size() >= 100 && server.clientCount() == 1)
            break; // the flood's client is closed
        for (const ControlLine& l : server.poll(16)) {
            server.answer(l.client, "ok " + l.text);
            if (l.text == "status")
                otherServed = true;
            else
                floodLines.push_back(l.text);
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    ASSERT_EQ(floodLines.size(), 100u);
    for (int i = 0; i < 100; ++i) {
        EXPECT_EQ(floodLines[i], "time " + std::to_string(i));
        EXPECT_EQ(flood.readLine(), "ok time " + std::to_string(i));
    }
    EXPECT_EQ(flood.readLine(), "error more than 100 lines per second; closing");
    EXPECT_EQ(flood.readLine(), ""); // closed
    EXPECT_TRUE(otherServed);
    EXPECT_EQ(other.readLine(), "ok status");
    EXPECT_EQ(server.clientCount(), 1u);
}

// A client that keeps within the rate is never cut off, however long it goes on: here 4 lines every
// half second (8 per second, 16 in all) against 10 per second, 10 at once.
TEST(ControlServer, AClientWithinTheRateIsServedThroughout)
{
    ControlServer server("127.0.0.1", 0, "", ControlServer::kIdleTimeoutS, 10.0);
    Client steady(server.port());
    size_t served = 0;
    for (int burst = 0; burst < 4; ++burst) {
        steady.send("status\nstatus\nstatus\nstatus\n");
        const auto next = std::chrono::steady_clock::now() + std::chrono::milliseconds(500);
        while (std::chrono::steady_clock::now() < next) {
            for (const ControlLine& l : server.poll(16)) {
                server.answer(l.client, "ok");
                ++served;
            }
            std::this_thread::sleep_for(std::chrono::milliseconds(2));
        }
    }
    EXPECT_EQ(served, 16u);
    EXPECT_EQ(server.clientCount(), 1u);
    for (size_t i = 0; i < served; ++i)
        EXPECT_EQ(steady.readLine(), "ok");
}
