#pragma once
// The exit status of every aurorawall command, and the one-line error on stderr.
//   0  success
//   1  runtime failure: the command line was accepted but the run failed (a file that cannot be read
//      or written or whose contents are malformed, no GL context, a shader that does not compile)
//   2  usage error: the command line itself is wrong (common/input_error.h, UsageError)
//   3  (render) a rank fell silent for longer than --rank-timeout, or its main thread hung (no
//      progress for longer than the timeout and 4 frames): the master ends the job
//      (cluster::kRankSilentExitStatus, cluster/watchdog.h)
//   128 + signal  (render) stopped by SIGINT or SIGTERM at a frame boundary: 130 or 143
#include <exception>
#include <functional>
#include <iosfwd>
#include <string>

namespace aurorawall::cli {

enum ExitStatus : int { kSuccess = 0, kRuntimeFailure = 1, kUsageError = 2 };

// kUsageError for a UsageError, kRuntimeFailure for any other exception.
int exitStatusOf(const std::exception& error);

// "aurorawall tables: message" (command "" gives "aurorawall: message"), one line.
std::string errorLine(const std::string& command, const std::string& message);

// Runs a command's body and turns what it throws into the exit status and one error line on `err`.
// Output that could not be written (a full disk, a closed pipe) is a runtime failure too.
int runCommand(const std::string& command, std::ostream& out, std::ostream& err, const std::function<void()>& body);

} // namespace aurorawall::cli
