#pragma once
// `aurorawall mie --n N --k K --x X [--angles-deg LIST]`: exact Mie scattering by one sphere, as CSV.
#include <iosfwd>

namespace aurorawall::components::glory::tools {

// argv[0] is the command's name ("mie"). Prints the CSV header
// `x,n,k,terms,qext,qsca,qabs,qback,g,s1_0_re,s1_0_im,s1_180_re,s1_180_im` and one row (10 significant
// digits; m = n − ik, k ≥ 0 absorbing); with --angles-deg, an empty line and the block
// `angle_deg,i_parallel,i_perpendicular,s1_re,s1_im,s2_re,s2_im`, one row per angle (i_parallel = |S2|²,
// i_perpendicular = |S1|²). Returns the exit status (cli/exit_status.h): 2 with one line on `err`
// naming the option for a bad or missing option (then nothing is printed on `out`), 1 if the output
// cannot be written.
int runMieCommand(int argc, char** argv, std::ostream& out, std::ostream& err);

} // namespace aurorawall::components::glory::tools
