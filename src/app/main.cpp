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

using namespace aurorawall;

// Every command: its name, its lines in `aurorawall --help`, and how it runs (it sees its own name
// as argv[0]). The usage text and the list of allowed names come from this one table.
struct Command {
    const char* name;
    const char* summary; // after the name; further lines indented by 12
    int (*run)(int argc, char** argv);
};

const Command kCommands[] = {
    {"render", "render a scene on a display wall, one MPI rank per group of screens\n"
               "            (mpirun -n RANKS aurorawall render --wall FILE --scene FILE ...)",
     [](int argc, char** argv) { return app::runRenderCommand(argc, argv); }},
    {"airmass", "airmass integrals along rays read from standard input (CSV), by a chosen method",
     [](int argc, char** argv) { return app::runAirmassCommand(argc, argv, std::cin, std::cout, std::cerr); }},
    {"tables", "print the precomputed physics tables (e.g. tables deposition --energy-kev 5)",
     [](int argc, char** argv) { return app::runTablesCommand(argc, argv, std::cout, std::cerr); }},
    {"accuracy", "error against cost of the approximations (accuracy --airmass | --sky | --scene FILE)",
     [](int argc, char** argv) { return app::runAccuracyCommand(argc, argv, std::cout, std::cerr); }},
    {"mie", "exact Mie scattering by one sphere (mie --n 1.33 --k 0 --x 100 [--angles-deg 0,180])",
     [](int argc, char** argv) { return app::runMieCommand(argc, argv, std::cout, std::cerr); }},
    {"plasma", "the particle-in-cell plasma: verify [--case NAME] against theory, soak --scene F (long\n"
               "            runs of a scene's plasma), accuracy (error against run time)",
     [](int argc, char** argv) { return app::runPlasmaCommand(argc, argv, std::cout, std::cerr); }},
};

std::string usage()
{
    std::string text = "aurorawall: a distributed powerwall renderer of the aurora borealis.\n"
                       "\n"
                       "Usage: aurorawall <command> [options]   (aurorawall <command> --help for its options)\n"
                       "\n"
                       "Commands:\n";
    for (const Command& c : kCommands)
        text += "  " + std::string(c.name) + std::string(10 - std::string(c.name).size(), ' ') + c.summary + "\n";
    return text +
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
}

std::string commandNames()
{
    std::string names;
    for (const Command& c : kCommands)
        names += (names.empty() ? "" : ", ") + std::string(c.name);
    return names;
}

} // namespace

int main(int argc, char** argv)
{
    const std::string command = argc > 1 ? argv[1] : "";
    const std::string seeHelp = " (see aurorawall --help)";
    if (command == "--help" || command == "-h") {
        std::cout << usage();
        return app::cli::kSuccess;
    }
    for (const Command& c : kCommands)
        if (command == c.name)
            return c.run(argc - 1, argv + 1);
    if (command.empty())
        std::cerr << app::cli::errorLine("", "missing command (allowed: " + commandNames() + ")" + seeHelp) << "\n";
    else if (command[0] == '-')
        std::cerr << app::cli::errorLine("", "unrecognised option '" + echoedInput(command) + "'" + seeHelp) << "\n";
    else
        std::cerr << app::cli::errorLine("", "unknown command '" + echoedInput(command) + "' (allowed: " + commandNames() +
                                            ")" + seeHelp)
                  << "\n";
    return app::cli::kUsageError;
}
