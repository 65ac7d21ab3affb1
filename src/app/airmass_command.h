#pragma once
// `aurorawall airmass [--method NAME]`: airmass of rays read as CSV from standard input.
#include <iosfwd>

namespace aurorawall::app {

// argv[0] is the command's name ("airmass"); the options follow. Reads lines
// `ox,oy,oz,dx,dy,dz,t0,t1,H,R` (km; a first line starting with a letter is a header; blank lines are
// skipped) and prints I in km, one per line, with 12 significant digits. Closed forms run in float32
// (the CPU twin of the shader); `exact` in double. Returns the exit status (cli/exit_status.h):
// 2 with one line on `err` for a bad option, 1 with one line naming the line number for a malformed
// line (then nothing is printed on `out`).
int runAirmassCommand(int argc, char** argv, std::istream& in, std::ostream& out, std::ostream& err);

} // namespace aurorawall::app
