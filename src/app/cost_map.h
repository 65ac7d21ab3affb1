#pragma once
// `render --cost-map FILE.png`: the cost of every pixel of the last frame as a colour, with a scale
// bar in nanoseconds per pixel (the per-pixel cost maps of Lawlor & Genetti's Figure 11).
//
// The cost of a pixel is its ray's work, written by the raymarcher to the float target's second
// attachment, times its rank's time per unit of work in that frame:
//     ns per work unit = render_ms of the rank * 1e6 / the summed work of the pixels it drew.
// The work is measured where the GPU has a clock: the cycles the pixel's ray took
// (render::PixelWork::ShaderClock); elsewhere it is 1 + the ray's texture fetches (TextureFetches),
// an estimate that gives every fetch the same cost and the rest of the ray none.
#include "app/wall_session.h"
#include "cluster/frame_stats.h"
#include "cluster/mpi_world.h"

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace aurorawall::app {

using Rgb8 = std::array<std::uint8_t, 3>; // 8-bit sRGB

// Matplotlib's viridis (van der Walt & Smith 2015, perceptually uniform, lightness increasing),
// linearly interpolated between 9 of its 256 entries; t is clamped to [0, 1].
Rgb8 viridis(double t);

// A logarithmic scale from the cheapest to the costliest pixel: position 0 at `low`, 1 at `high`.
struct CostScale {
    double low = 1.0;
    double high = 1.0;
    double position(double cost) const; // clamped to [0, 1]; 0 when high <= low
};

// An 8-bit sRGB picture, rows top-down.
struct Picture {
    int width = 0, height = 0;
    std::vector<std::uint8_t> rgb; // 3 bytes a pixel
    Rgb8 at(int x, int y) const;
};

// The rows of the scale bar below a map `width` pixels wide.
int scaleBarHeight(int width);

// The map of costs (ns per pixel, rows top-down, width * height of them; <= 0 where nothing was
// drawn, the bezels: black) on a log scale from the smallest to the largest positive cost, with the
// scale bar below it: a viridis strip, ticks labelled in ns, and the caption "ns per pixel estimate".
// The picture is width x (height + scaleBarHeight(width)).
Picture costMapPicture(int width, int height, const std::vector<double>& costNs);

// Writes the picture as an opaque RGB PNG, atomically (io/atomic_file.h). Throws std::runtime_error.
void writePicturePng(const std::string& path, const Picture& picture);

// Every rank reads the work of its screens' last frame and sends it to the master (4 bytes a
// pixel), which converts it to time with each rank's render time of the last frame in `stats` and
// writes session.options.costMapFile. Needs the static split (each screen's work is in its own
// rank's target). Collective; returns the exit status every rank agrees on.
int writeCostMap(WallSession& session, const cluster::MpiWorld& world, const cluster::FrameStats& stats);

} // namespace aurorawall::app
