#pragma once
// SIGINT and SIGTERM end a render cleanly: the handler only notes the signal; each rank reports it
// with its frame (RankReport::stopSignal), the master then decides a quit frame that every rank
// sees, and the outputs of the frames drawn are written as after a `quit`. No rank stops in the
// middle of a collective. mpirun passes SIGINT and SIGTERM on to every rank as SIGTERM; a signal
// sent to one rank stops the whole wall the same way.
namespace aurorawall::app {

// Installs the handlers (SA_RESTART, so interrupted system calls resume).
void catchStopSignals();

// The stop signal received (SIGINT or SIGTERM), or 0.
int stopSignal();

} // namespace aurorawall::app
