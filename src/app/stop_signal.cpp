#include "app/stop_signal.h"

#include <csignal>

namespace aurorawall::app {

namespace {

volatile std::sig_atomic_t received = 0;

void note(int signal) { received = signal; }

} // namespace

void catchStopSignals()
{
    struct sigaction action {};
    action.sa_handler = note;
    sigemptyset(&action.sa_mask);
    action.sa_flags = SA_RESTART;
    sigaction(SIGINT, &action, nullptr);
    sigaction(SIGTERM, &action, nullptr);
}

int stopSignal() { return received; }

} // namespace aurorawall::app
