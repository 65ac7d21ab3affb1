#include "app/render_command.h"

#include "app/cli/exit_status.h"
#include "app/frame_loop.h"
#include "app/wall_output.h"
#include "app/wall_session.h"
#include "cluster/mpi_world.h"

#include <cstdio>
#include <exception>
#include <string>

namespace aurorawall::app {

int runRenderCommand(int argc, char** argv)
{
    cluster::MpiWorld world(&argc, &argv);
    WallSession session;
    const int status = setUpWallSession(world, argc, argv, session);
    if (status != cli::kSuccess || session.options.help || session.options.printRanks)
        return status;
    // A failure in the middle of a frame (a corrupt band from another rank, a GPU simulation that
    // cannot be rebuilt) ends the whole job with one line: the other ranks may be waiting for this one.
    try {
        const cluster::FrameStats stats = runFrames(session, world);
        return writeOutputs(session, world, stats);
    } catch (const std::exception& error) {
        std::fprintf(stderr, "%s\n",
                     cli::errorLine("render", "rank " + std::to_string(world.rank()) + ": " + error.what()).c_str());
        world.abortJob(cli::kRuntimeFailure);
    }
}

} // namespace aurorawall::app
