#pragma once
// This rank's part of a frame: it draws the bands the master assigned to it (cluster/load_balancer.h)
// and ends with every band of its own screens in their float targets.
// - A band of one of its own screens is drawn straight into that screen's target: it never leaves the GPU.
// - A band of another rank's screen is drawn into a scratch target of that screen's size, read back,
//   rounded to half floats (io/half_pixels.h, 6 bytes a pixel), compressed losslessly
//   (io/band_compression.h) and sent to the screen's rank, which decompresses it and uploads it into
//   its target's rows; a block that does not decompress to the band's halves is an error naming
//   the rank, the band and its sender.
// Every band is drawn with its screen's rays over its own rows of a target of the screen's size (a
// scissor keeps the other rows), so it gets the same floats whoever draws it; the output rounds every
// screen to half floats, and a half rounds to itself, so the balanced wall equals the static one bit
// for bit (tests/app/balance.sh).
#include "app/screen_target.h"
#include "cluster/load_balancer.h"
#include "cluster/mpi_world.h"
#include "cluster/rank_message.h"
#include "gl/context.h"
#include "render/tile_renderer.h"
#include "wall/wall.h"

#include <cstdint>
#include <map>
#include <memory>
#include <utility>
#include <vector>

namespace aurorawall::app {

// The halves of band `bandIndex` of a screen `widthPx` wide, decompressed from the bytes that rank
// `sender` sent to rank `rank`. Throws std::runtime_error, one line naming the rank, the band
// (screen, rows) and the sender, unless the bytes are that band's compressed halves.
std::vector<std::uint16_t> receivedBandPixels(const std::vector<std::uint8_t>& bytes, const cluster::Band& band,
                                              int bandIndex, int widthPx, int rank, int sender);

class BandFrame {
public:
    // measureCosts: report each drawn band's cost (the load balancer's input), read from the work
    // the raymarcher writes to the target's attachment 1.
    BandFrame(const wall::Wall& wall, std::vector<cluster::Band> bands, int rank, bool measureCosts);

    // Draws this rank's bands of `assignment` (band -> rank) and exchanges those drawn away from
    // their screen; fills the report's render and exchange fields (exchangeMB: the compressed bytes
    // sent and received; exchangeMs includes compressing and decompressing). Returns each drawn band's cost when
    // measuring costs, else nothing. Needs window 0's context current and leaves it current.
    std::vector<cluster::BandCost> draw(render::TileRenderer& renderer, gl::Context& context,
                                        std::vector<ScreenTarget>& screens, const std::vector<std::int32_t>& assignment,
                                        const cluster::MpiWorld& world, cluster::RankReport& report);

private:
    // Where bands of other ranks' screens are drawn (window 0's context), one per screen size.
    struct Scratch {
        std::unique_ptr<gl::FloatTarget> target;
        std::unique_ptr<gl::FullScreenTriangle> triangle;
        std::unique_ptr<gl::GpuTimer> drawTimer;
    };
    Scratch& scratchFor(int width, int height);

    // Bands of other ranks' screens drawn here, as half-float RGB, and their indices.
    struct OutgoingBands {
        std::vector<std::vector<std::uint16_t>> pixels;
        std::vector<int> bands;
    };
    // Draws the run of my bands [first, end), all of one screen, in one draw (a draw has a fixed cost,
    // and rasterizers shade whole pixel blocks). Bands of other ranks' screens are read back at once
    // (the next run may draw into the same scratch target) into `outgoing`. The frame's first run
    // (`firstOfFrame`) is flushed and the components' work for the next frame done while it draws
    // (TileRenderer::whileDrawing), its CPU time left out of the run's.
    void drawRun(size_t first, size_t end, bool firstOfFrame, render::TileRenderer& renderer, gl::Context& context,
                 std::vector<ScreenTarget>& screens, cluster::RankReport& report,
                 std::vector<cluster::BandCost>& costs, OutgoingBands& outgoing);
    // The run's cost `runMs` (its GPU time, or its process CPU time on Mesa's CPU renderers) shared among
    // its bands in proportion to their rays' work (the target's attachment 1, rows of a screen
    // `screenHeight` tall); the work added to the report.
    void shareRunCost(size_t first, size_t end, const gl::FloatTarget& target, int screenHeight, double runMs,
                      cluster::RankReport& report, std::vector<cluster::BandCost>& costs) const;
    // Other screens' bands go out compressed (io/band_compression.h, lossless), my screens' bands
    // drawn elsewhere come in and go into their rows of my screens' targets.
    void exchange(const OutgoingBands& outgoing, gl::Context& context, std::vector<ScreenTarget>& screens,
                  const std::vector<std::int32_t>& assignment, const cluster::MpiWorld& world,
                  cluster::RankReport& report) const;

    const wall::Wall& wall_;
    std::vector<cluster::Band> bands_;
    int rank_;
    bool measureCosts_;
    std::map<std::pair<int, int>, Scratch> scratch_;
};

} // namespace aurorawall::app
