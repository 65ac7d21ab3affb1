#pragma once
// `aurorawall tables deposition --energy-kev E [--maxwellian]`: the Lazarev deposition profile as CSV;
// `aurorawall tables NAME --scene FILE`: a component's table of a scene (components/tools.h).
#include <iosfwd>

namespace aurorawall::app {

// argv[0] is the command's name ("tables"), then the table ("deposition") and the options. Prints
// `altitude_km,rate` then one line per 0.5 km from 60 to 600 km; rate is the energy deposition rate in
// keV cm⁻³ s⁻¹ per erg cm⁻² s⁻¹ of incident energy flux (electrons of energy E, or a Maxwellian of
// characteristic energy E), 10 significant digits. Returns the exit status (cli/exit_status.h):
// 2 with one line on `err` naming the option for a bad or missing option (then nothing is printed on
// `out`), 1 if the output cannot be written.
int runTablesCommand(int argc, char** argv, std::ostream& out, std::ostream& err);

} // namespace aurorawall::app
