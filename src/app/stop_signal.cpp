#include "app/stop_signal.h"

#include <cerrno>
#include <csignal>

#include <fcntl.h>
#include <sys/stat.h>
#include <termios.h>
#include <unistd.h>

namespace aurorawall::app {

namespace {

volatile std::sig_atomic_t received = 0;

// Standard output and error, and whether each may stop blocking at a stop signal (readerMayStop).
constexpr int kStreams[] = {STDOUT_FILENO, STDERR_FILENO};
bool mayStopBlocking[3] = {false, false, false};

void note(int signal)
{
    const int saved = errno;
    received = signal;
    // Writes that would block fail from now on (fcntl is async-signal-safe; a write blocked now is
    // restarted and fails at once).
    for (const int fd : kStreams)
        if (mayStopBlocking[fd]) {
            const int flags = fcntl(fd, F_GETFL);
            if (flags >= 0)
                fcntl(fd, F_SETFL, flags | O_NONBLOCK);
        }
    errno = saved;
}

// A pipe, a socket, or a terminal that is not this process's controlling terminal (mpirun gives each
// rank a pseudo-terminal of its own): never the terminal that a shell shares, whose flags it would keep.
bool readerMayStop(int fd)
{
    struct stat s {};
    if (fstat(fd, &s) != 0)
        return false;
    return S_ISFIFO(s.st_mode) || S_ISSOCK(s.st_mode) || (isatty(fd) && tcgetsid(fd) == -1);
}

} // namespace

void catchStopSignals()
{
    for (const int fd : kStreams)
        mayStopBlocking[fd] = readerMayStop(fd);
    struct sigaction action {};
    action.sa_handler = note;
    sigemptyset(&action.sa_mask);
    action.sa_flags = SA_RESTART;
    sigaction(SIGINT, &action, nullptr);
    sigaction(SIGTERM, &action, nullptr);
}

int stopSignal() { return received; }

} // namespace aurorawall::app
