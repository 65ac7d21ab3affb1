// aurorawall: one binary, several subcommands.
#include "app/accuracy_scene.h"
#include "app/render_command.h"
#include "atmosphere/accuracy_cli.h"
#include "atmosphere/airmass_cli.h"
#include "aurora/tables_cli.h"

#include <cstdio>
#include <cstring>
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
    "  accuracy  error against cost of the approximations (accuracy --airmass | --sky | --scene FILE)\n";

} // namespace

int main(int argc, char** argv)
{
    if (argc < 2 || !std::strcmp(argv[1], "--help") || !std::strcmp(argv[1], "-h") || !std::strcmp(argv[1], "help")) {
        std::fputs(kUsage, argc < 2 ? stderr : stdout);
        return argc < 2 ? 2 : 0;
    }
    const std::string command = argv[1];
    // Each command sees its own name as argv[0].
    if (command == "render")
        return aurorawall::app::runRenderCommand(argc - 1, argv + 1);
    if (command == "airmass")
        return aurorawall::runAirmassCommand(argc - 1, argv + 1, std::cin, std::cout, std::cerr);
    if (command == "accuracy") {
        // --scene: the aurora's quality knobs (src/app/accuracy_scene.h); else airmass and sky.
        for (int i = 2; i < argc; ++i)
            if (!std::strcmp(argv[i], "--scene"))
                return aurorawall::app::runSceneAccuracy(argc - 1, argv + 1, std::cout, std::cerr);
        return aurorawall::runAccuracyCommand(argc - 1, argv + 1, std::cout, std::cerr);
    }
    if (command == "tables")
        return aurorawall::aurora::runTablesCommand(argc - 1, argv + 1, std::cout, std::cerr);
    std::fprintf(stderr, "aurorawall: unknown command '%s'\n%s", command.c_str(), kUsage);
    return 2;
}
