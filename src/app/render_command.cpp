#include "app/render_command.h"

#include "app/cli/exit_status.h"
#include "app/frame_loop.h"
#include "app/wall_output.h"
#include "app/wall_session.h"
#include "cluster/mpi_world.h"

namespace aurorawall::app {

int runRenderCommand(int argc, char** argv)
{
    cluster::MpiWorld world(&argc, &argv);
    WallSession session;
    const int status = setUpWallSession(world, argc, argv, session);
    if (status != cli::kSuccess || session.options.help)
        return status;
    const cluster::FrameStats stats = runFrames(session, world);
    return writeOutputs(session, world, stats);
}

} // namespace aurorawall::app
