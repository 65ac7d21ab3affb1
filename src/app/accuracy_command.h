#pragma once
// `aurorawall accuracy --airmass | --sky | --scene FILE`: error against cost of the approximations
// (docs/ACCURACY.md), one command line that dispatches to the airmass and sky tables
// (physics/atmosphere/accuracy_report.h), to the sweep of a scene's quality knobs or to a component's table
// (components/tools.h).
#include <iosfwd>

namespace aurorawall::app {

// argv[0] is the command's name ("accuracy"); see --help. Returns the exit status
// (cli/exit_status.h): 2 with one line on `err` for a bad option, 1 with one line when a file
// cannot be read or is malformed or when no GL context or shader can be made.
int runAccuracyCommand(int argc, char** argv, std::ostream& out, std::ostream& err);

} // namespace aurorawall::app
