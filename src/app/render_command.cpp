#include "app/render_command.h"

#include "app/frame_loop.h"
#include "app/wall_output.h"
#include "app/wall_session.h"
#include "cluster/mpi_world.h"

namespace aurorawall::app {

int runRenderCommand(int argc, char** argv)
{
    cluster::MpiWorld world(&argc, &argv);
    WallSession session;
    switch (setUpWallSession(world, argc, argv, session)) {
    case SetUpOutcome::Failed: return 1;
    case SetUpOutcome::HelpShown: return 0;
    case SetUpOutcome::Ready: break;
    }
    const cluster::FrameStats stats = runFrames(session, world);
    return writeOutputs(session, world, stats) ? 0 : 1;
}

} // namespace aurorawall::app
