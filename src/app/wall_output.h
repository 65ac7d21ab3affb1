#pragma once
// What `aurorawall render` writes after its last frame: each rank's screens as tile EXRs (--tiles),
// the wall assembled on the master as wall.exr and wall.png (--gather), and the statistics (--stats).
#include "app/wall_session.h"
#include "cluster/frame_stats.h"
#include "cluster/mpi_world.h"
#include "io/image.h"

namespace aurorawall::app {

// Every rank reads back its screens (rounded to half floats, as the outputs are) and sends them to the
// master, which assembles the wall's canvas into `canvas` (bezels black); other ranks leave it alone.
// Collective. Returns the exit status every rank agrees on (1 if a readback failed).
int gatherWallImage(WallSession& session, const cluster::MpiWorld& world, io::Image& canvas);

// Returns the exit status every rank agrees on: 0 if every file was written, else 1 (rank 0 has
// printed why). The master prints the statistics' summary either way.
int writeOutputs(WallSession& session, const cluster::MpiWorld& world, const cluster::FrameStats& stats);

} // namespace aurorawall::app
