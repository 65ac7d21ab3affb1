#pragma once
// `aurorawall plasma verify [--case NAME] [--device cpu|gpu] [--wp-dt X] [--wc-dt X]`: the particle-in-cell plasma's
// verification cases as CSV (docs/PLASMA.md).
#include <iosfwd>

namespace aurorawall::components::plasma::tools {

// argv[0] is the command's name ("plasma"), then the action ("verify") and the options. Prints
// `case,parameter,measured,expected,rel_error`, one row per measured quantity (expected computed
// from theory) or setting of a run (expected and rel_error empty). Returns the exit status
// (cli/exit_status.h): 2 with one line on `err` naming the option for a bad option (then nothing
// is printed on `out`), 1 if a run fails or the output cannot be written.
int runPlasmaCommand(int argc, char** argv, std::ostream& out, std::ostream& err);

} // namespace aurorawall::components::plasma::tools
