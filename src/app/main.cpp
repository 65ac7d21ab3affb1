// aurorawall: one binary, several commands.
#include "app/accuracy_command.h"
#include "app/airmass_command.h"
#include "app/cli/exit_status.h"
#include "app/mie_command.h"
#include "app/plasma_command.h"
#include "app/render_command.h"
#include "app/tables_command.h"
#include "common/input_error.h"

#include <iostream>
#include <string>

namespace {

const char* kUsage =
    "aurorawall: a distributed powerwall renderer of the aurora borealis.\n"
    "\n"
    "Usage: aurorawall <command> [options]   (aurorawall <command> --help for its options)\n"
    "\n"
    "Commands:\n"
    "  render    render a scene on a display wall, one MPI rank per group of screens\n"
    "            (mpirun -n RANKS aurorawall render --wall FILE --scene FILE ...)\n"
    "  airmass   airmass integrals along rays read from standard input (CSV), by a chosen method\n"
    "  tables    print the precomputed physics tables (e.g. tables deposition --energy-kev 5)\n"
    "  accuracy  error against cost of the approximations (accuracy --airmass | --sky | --scene FILE)\n"
    "  mie       exact Mie scattering by one sphere (mie --n 1.33 --k 0 --x 100 [--angles-deg 0,180])\n"
    "  plasma    the particle-in-cell plasma: verify [--case NAME] against theory, soak --scene F (long\n"
    "            runs of a scene's plasma), accuracy (error against run time)\n"
    "\n"
    "Exit status, the same for every command (and, under mpirun, on every rank):\n"
    "  0  success\n"
    "  1  runtime failure: the command line was accepted, but the run failed: a file that cannot be read\n"
    "     or written, a wall, scene or input file whose contents are malformed (the error names FILE:LINE),\n"
    "     no GL context, a shader that does not compile\n"
    "  2  usage error: the command line itself is wrong: an unknown command, an unknown, missing or\n"
    "     repeated option, a malformed value, a value out of range or not among the allowed words,\n"
    "     options that contradict each other, or a number of MPI ranks other than the wall file's\n"
    "Errors are one line on stderr: \"aurorawall COMMAND: ...\", naming the option or FILE:LINE.\n";

const char* kCommands = "render, airmass, tables, accuracy, mie, plasma";

} // namespace

int main(int argc, char** argv)
{
    using namespace aurorawall;
    const std::string command = argc > 1 ? argv[1] : "";
    const std::string seeHelp = " (see aurorawall --help)";
    if (command == "--help" || command == "-h") {
        std::cout << kUsage;
        return cli::kSuccess;
    }
    // Each command sees its own name as argv[0].
    if (command == "render")
        return app::runRenderCommand(argc - 1, argv + 1);
    if (command == "airmass")
        return app::runAirmassCommand(argc - 1, argv + 1, std::cin, std::cout, std::cerr);
    if (command == "tables")
        return app::runTablesCommand(argc - 1, argv + 1, std::cout, std::cerr);
    if (command == "accuracy")
        return app::runAccuracyCommand(argc - 1, argv + 1, std::cout, std::cerr);
    if (command == "mie")
        return app::runMieCommand(argc - 1, argv + 1, std::cout, std::cerr);
    if (command == "plasma")
        return app::runPlasmaCommand(argc - 1, argv + 1, std::cout, std::cerr);
    if (command.empty())
        std::cerr << cli::errorLine("", std::string("missing command (allowed: ") + kCommands + ")" + seeHelp) << "\n";
    else if (command[0] == '-')
        std::cerr << cli::errorLine("", "unrecognised option '" + echoedInput(command) + "'" + seeHelp) << "\n";
    else
        std::cerr << cli::errorLine("", "unknown command '" + echoedInput(command) + "' (allowed: " + kCommands + ")" + seeHelp)
                  << "\n";
    return cli::kUsageError;
}
