// `aurorawall accuracy` as a program of its own (the same function), for launch/accuracy-airmass
// until the subcommand is wired into src/app/main.cpp.
#include "atmosphere/accuracy_cli.h"

#include <iostream>

int main(int argc, char** argv)
{
    return aurorawall::runAccuracyCommand(argc, argv, std::cout, std::cerr);
}
