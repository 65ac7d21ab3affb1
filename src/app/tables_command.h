#pragma once
// `aurorawall tables NAME --OPTION VALUE ...`: a component's table of options alone;
// `aurorawall tables NAME --scene FILE`: a component's table of a scene. Both kinds come from the components' tools (components/tools.h).
#include <iosfwd>

namespace aurorawall::app {

// argv[0] is the command's name ("tables"), then the table's name and its options. Prints the table
// as CSV. Returns the exit status (cli/exit_status.h): 2 with one line on `err` naming the option for
// a bad or missing option (then nothing is printed on `out`), 1 if the output cannot be written or
// the scene not read.
int runTablesCommand(int argc, char** argv, std::ostream& out, std::ostream& err);

} // namespace aurorawall::app
