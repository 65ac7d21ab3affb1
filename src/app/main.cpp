// aurorawall: one binary, several commands.
#include "app/accuracy_command.h"
#include "app/airmass_command.h"
#include "cli/exit_status.h"
#include "app/render_command.h"
#include "app/tables_command.h"
#include "common/input_error.h"
#include "components/tools.h"

#include <iostream>
#include <iterator>
#include <string>
#include <vector>

namespace {

using namespace aurorawall;

using components::Command;

// The generic commands: their names, their lines in `aurorawall --help`, and how they run (each sees
// its own name as argv[0]). The components' commands follow them (components/tools.h); the usage
// text and the list of allowed names come from both.
const Command kGenericCommands[] = {
    {"render", "render a scene on a display wall, one MPI rank per group of screens\n"
               "            (mpirun -n RANKS aurorawall render --wall FILE --scene FILE ...)",
     [](int argc, char** argv, std::ostream&, std::ostream&) { return app::runRenderCommand(argc, argv); }},
    {"airmass", "airmass integrals along rays read from standard input (CSV), by a chosen method",
     [](int argc, char** argv, std::ostream& out, std::ostream& err) {
         return app::runAirmassCommand(argc, argv, std::cin, out, err);
     }},
    {"tables", "print the precomputed physics tables (e.g. tables deposition --energy-kev 5)", app::runTablesCommand},
    {"accuracy", "error against cost of the approximations (accuracy --airmass | --sky | --scene FILE)",
     app::runAccuracyCommand},
};

std::vector<Command> allCommands()
{
    std::vector<Command> all(std::begin(kGenericCommands), std::end(kGenericCommands));
    const std::vector<Command>& tools = components::componentCommands();
    all.insert(all.end(), tools.begin(), tools.end());
    return all;
}

std::string usage()
{
    std::string text = "aurorawall: a distributed powerwall renderer of the aurora borealis.\n"
                       "\n"
                       "Usage: aurorawall <command> [options]   (aurorawall <command> --help for its options)\n"
                       "\n"
                       "Commands:\n";
    for (const Command& c : allCommands())
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
           "  3  render only: a rank sent no heartbeat for --rank-timeout seconds; the master ends the job\n"
           "  130, 143  render only: stopped by SIGINT or SIGTERM at a frame boundary, the frames drawn written\n"
           "Errors are one line on stderr: \"aurorawall COMMAND: ...\", naming the option or FILE:LINE.\n";
}

std::string commandNames()
{
    std::string names;
    for (const Command& c : allCommands())
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
        return cli::kSuccess;
    }
    for (const Command& c : allCommands())
        if (command == c.name)
            return c.run(argc - 1, argv + 1, std::cout, std::cerr);
    if (command.empty())
        std::cerr << cli::errorLine("", "missing command (allowed: " + commandNames() + ")" + seeHelp) << "\n";
    else if (command[0] == '-')
        std::cerr << cli::errorLine("", "unrecognised option '" + common::echoedInput(command) + "'" + seeHelp) << "\n";
    else
        std::cerr << cli::errorLine("", "unknown command '" + common::echoedInput(command) + "' (allowed: " + commandNames() +
                                            ")" + seeHelp)
                  << "\n";
    return cli::kUsageError;
}
