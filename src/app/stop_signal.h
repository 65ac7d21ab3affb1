#pragma once
// SIGINT and SIGTERM end a render cleanly: the handler only notes the signal; each rank reports it
// with its frame (RankReport::stopSignal), the master then decides a quit frame that every rank
// sees, and the outputs of the frames drawn are written as after a `quit`. No rank stops in the
// middle of a collective. mpirun passes SIGINT and SIGTERM on to every rank as SIGTERM; a signal
// sent to one rank stops the whole wall the same way.
// Open MPI stops reading the ranks' output when it gets SIGINT, sends SIGTERM a second later and
// kills the ranks that have not ended a second after that: a rank that printed a line a frame would
// sit blocked on a full pipe and never reach the frame where it stops. So from the signal on, writes
// to a standard output or error that is a pipe, a socket or a pseudo-terminal of the rank's own fail
// instead of blocking (what they would have printed nobody reads); the terminal a shell shares, and a
// file, are left as they are.
namespace aurorawall::app {

// Installs the handlers (SA_RESTART, so interrupted system calls resume).
void catchStopSignals();

// The stop signal received (SIGINT or SIGTERM), or 0.
int stopSignal();

} // namespace aurorawall::app
