#pragma once
namespace aurorawall::app {

// `aurorawall render ...` under mpirun. Returns the exit status (cli/exit_status.h), the same
// on every rank: the largest over the ranks, so a usage error on any rank makes every rank exit 2.
int runRenderCommand(int argc, char** argv);

} // namespace aurorawall::app
