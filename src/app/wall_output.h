#pragma once
// What `aurorawall render` writes after its last frame: each rank's screens as tile EXRs (--tiles),
// the wall assembled on the master as wall.exr and wall.png (--gather), and the statistics (--stats).
#include "app/wall_session.h"
#include "cluster/frame_stats.h"
#include "cluster/mpi_world.h"

namespace aurorawall::app {

// Returns the exit status every rank agrees on: 0 if every file was written, else 1 (rank 0 has
// printed why). The master prints the statistics' summary either way.
int writeOutputs(WallSession& session, const cluster::MpiWorld& world, const cluster::FrameStats& stats);

} // namespace aurorawall::app
