#pragma once
namespace aurorawall::app {

// `aurorawall render ...` under mpirun. Returns the process exit code (0: success); every rank
// returns non-zero if any rank failed during set-up.
int runRenderCommand(int argc, char** argv);

} // namespace aurorawall::app
