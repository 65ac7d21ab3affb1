#pragma once
// What `aurorawall render` writes after its last frame: each rank's screens as tile EXRs (--tiles),
// the wall assembled on the master as wall.exr and wall.png (--gather), and the statistics (--stats);
// and, every frame, the movie's frames (--movie).
#include "app/wall_session.h"
#include "cluster/frame_stats.h"
#include "cluster/frame_state.h"
#include "cluster/mpi_world.h"
#include "io/image.h"
#include "io/tone_map.h"

#include <string>

namespace aurorawall::app {

// Every rank reads back its screens (rounded to half floats, as the outputs are) and sends them to the
// master, which assembles the wall's canvas into `canvas` (bezels black); other ranks leave it alone.
// Collective. Returns the exit status every rank agrees on (1 if a readback failed).
int gatherWallImage(WallSession& session, const cluster::MpiWorld& world, io::Image& canvas);

// The movie of --movie, written by the master: each frame's gathered wall as DIR/frame-NNNNNN.png
// (NNNNNN: the frame number), with --movie-exr also DIR/frame-NNNNNN.exr, and DIR/frames.csv listing
// every frame written so far with its exact animation time ("frame,time_s", %.17g: the double
// itself). Every file is written atomically (io/atomic_file.h); a failure throws.
class MovieWriter {
public:
    MovieWriter(std::string dir, bool exr, io::ToneMap toneMap);
    void write(const io::Image& canvas, const cluster::FrameState& state);
    // The list of the frames written, in the movie's folder.
    static constexpr const char* kFramesList = "frames.csv";
    // Whether `name` is the name of a file a movie writer writes (frame-NNNNNN.png or .exr, kFramesList).
    static bool writes(const std::string& name);

private:
    std::string dir_;
    bool exr_;
    io::ToneMap toneMap_;
    std::string csv_ = "frame,time_s\n";
};

// The tile EXR that --tiles writes for the screen named `screenName` into outDir.
std::string tilePath(const std::string& outDir, const std::string& screenName);

// Returns the exit status every rank agrees on: 0 if every file was written, else 1 (rank 0 has
// printed why; a movie frame that could not be written, session.movieError, counts). The master prints the statistics' summary either way.
int writeOutputs(WallSession& session, const cluster::MpiWorld& world, const cluster::FrameStats& stats);

} // namespace aurorawall::app
