#include "app/render_command.h"

#include "cli/exit_status.h"
#include "app/frame_loop.h"
#include "app/stop_signal.h"
#include "app/wall_output.h"
#include "app/wall_session.h"
#include "cluster/mpi_world.h"

#include <csignal>
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
        catchStopSignals();
        const cluster::FrameStats stats = runFrames(session, world);
        const int written = writeOutputs(session, world, stats);
        // Every rank exits alike: with 128 + the signal the master reported, which it broadcasts.
        const int signal = world.broadcastInt(session.stoppedBySignal);
        if (signal == 0)
            return written;
        if (world.isMaster())
            std::fprintf(stderr, "%s\n",
                         cli::errorLine("render", std::string("stopped by ") + (signal == SIGINT ? "SIGINT" : "SIGTERM") +
                                                      " after " + std::to_string(stats.records().size()) +
                                                      " frames; the outputs of those frames are written")
                             .c_str());
        return written != cli::kSuccess ? written : 128 + signal;
    } catch (const std::exception& error) {
        std::fprintf(stderr, "%s\n",
                     cli::errorLine("render", "rank " + std::to_string(world.rank()) + ": " + error.what()).c_str());
        world.abortJob(cli::kRuntimeFailure);
    }
}

} // namespace aurorawall::app
