#pragma once
// The frame loop of `aurorawall render`. Per frame, exactly one broadcast from the master (the
// FrameMessage: frame state, band assignment, input events, HUD) and one gather to the master (each
// rank's RankMessage: its report and its bands' costs), with the band exchange between them; with
// windows also the swap barrier before the flip.
#include "app/wall_session.h"
#include "cluster/frame_stats.h"
#include "cluster/mpi_world.h"

namespace aurorawall::app {

// Runs frames until the master's clock has given --frames of them, a window asks to close or the
// remote control (session.control, master only) says quit; carries out its commands before each frame.
// Returns the master's statistics (other ranks: empty).
cluster::FrameStats runFrames(WallSession& session, const cluster::MpiWorld& world);

} // namespace aurorawall::app
