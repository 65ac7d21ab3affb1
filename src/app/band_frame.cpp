#include "app/band_frame.h"

#include "common/clock.h"
#include "gl/functions.h"
#include "io/band_compression.h"
#include "io/half_pixels.h"
#include "wall/tile_rays.h"

#include <stdexcept>
#include <string>

namespace aurorawall::app {

namespace {

// The first of a band's rows in GL's bottom-up order, on a screen `screenHeight` rows tall (bands
// count their rows from the top).
int firstGlRow(const cluster::Band& band, int screenHeight) { return screenHeight - band.y0 - band.height; }

// Draws rows [firstRow, firstRow + rows) of `target` (GL order) with the screen's rays: the same
// fragments as a draw of the whole screen, the other rows left as they are.
void drawRows(render::TileRenderer& renderer, const wall::TileRays& rays, gl::FloatTarget& target,
              const gl::FullScreenTriangle& triangle, int firstRow, int rows)
{
    gl::glEnable(GL_SCISSOR_TEST);
    gl::glScissor(0, firstRow, target.width(), rows);
    renderer.renderTile(rays, target, triangle);
    gl::glDisable(GL_SCISSOR_TEST);
}

// RGB floats rounded to half floats where they leave the GPU.
std::vector<std::uint16_t> rgbHalves(const std::vector<float>& rgb)
{
    std::vector<std::uint16_t> halves(rgb.size());
    for (size_t i = 0; i < rgb.size(); ++i)
        halves[i] = io::halfBits(rgb[i]);
    return halves;
}

} // namespace

std::vector<std::uint16_t> receivedBandPixels(const std::vector<std::uint8_t>& bytes, const cluster::Band& band,
                                              int bandIndex, int widthPx, int rank, int sender)
{
    try {
        return io::decompressHalves(bytes, 3 * size_t(widthPx) * size_t(band.height), 3);
    } catch (const std::runtime_error& e) {
        throw std::runtime_error("rank " + std::to_string(rank) + ": band " + std::to_string(bandIndex) + " (screen " +
                                 std::to_string(band.screen) + ", rows " + std::to_string(band.y0) + "-" +
                                 std::to_string(band.y0 + band.height - 1) + ") from rank " + std::to_string(sender) +
                                 ": " + e.what());
    }
}

BandFrame::BandFrame(const wall::Wall& wall, std::vector<cluster::Band> bands, int rank, bool measureCosts)
    : wall_(wall), bands_(std::move(bands)), rank_(rank), measureCosts_(measureCosts)
{
}

BandFrame::Scratch& BandFrame::scratchFor(int width, int height)
{
    Scratch& s = scratch_[{width, height}];
    if (!s.target) {
        s.target = std::make_unique<gl::FloatTarget>(width, height);
        s.triangle = std::make_unique<gl::FullScreenTriangle>();
        s.drawTimer = std::make_unique<gl::GpuTimer>();
    }
    return s;
}

std::vector<cluster::BandCost> BandFrame::draw(render::TileRenderer& renderer, gl::Context& context,
                                               std::vector<ScreenTarget>& screens,
                                               const std::vector<std::int32_t>& assignment,
                                               const cluster::MpiWorld& world, cluster::RankReport& report)
{
    // 1. Draw my bands, one run of consecutive bands of one screen at a time.
    std::vector<cluster::BandCost> costs;
    OutgoingBands outgoing;
    const auto start = common::SteadyClock::now();
    const double cpuStart = common::processCpuMilliseconds();
    // 0 for a rank of a device with timer queries that draws no band this frame.
    report.renderGpuMs = !screens.empty() && screens.front().drawTimer->usesQueries() ? 0.0 : -1.0;
    bool drewRun = false;
    for (size_t first = 0; first < bands_.size();) {
        if (assignment[first] != rank_) {
            ++first;
            continue;
        }
        size_t end = first + 1;
        while (end < bands_.size() && assignment[end] == rank_ && bands_[end].screen == bands_[first].screen)
            ++end;
        drawRun(first, end, !drewRun, renderer, context, screens, report, costs, outgoing);
        drewRun = true;
        first = end;
    }
    report.renderMs = common::millisecondsSince(start);
    report.renderCpuMs = common::processCpuMilliseconds() - cpuStart;

    // 2. Exchange the bands drawn away from their screens.
    exchange(outgoing, context, screens, assignment, world, report);
    return costs;
}

void BandFrame::drawRun(size_t first, size_t end, bool firstOfFrame, render::TileRenderer& renderer, gl::Context& context,
                        std::vector<ScreenTarget>& screens, cluster::RankReport& report,
                        std::vector<cluster::BandCost>& costs, OutgoingBands& outgoing)
{
    const cluster::Band& top = bands_[first];
    const cluster::Band& bottom = bands_[end - 1];
    const wall::Screen& screen = wall_.screens[top.screen];
    const bool myScreen = top.owner == rank_;
    ScreenTarget* own = myScreen ? &screenTarget(screens, top.screen) : nullptr;
    context.makeCurrent(myScreen ? own->window : 0); // before a scratch target's vertex array and queries are made
    Scratch* scratch = myScreen ? nullptr : &scratchFor(screen.widthPx, screen.heightPx);
    gl::FloatTarget& target = myScreen ? *own->target : *scratch->target;
    gl::GpuTimer& timer = myScreen ? *own->drawTimer : *scratch->drawTimer;

    // The run's cost: the GPU's time where it has timer queries; on Mesa's CPU renderers, whose draw runs on
    // this process's threads, its CPU time (on a shared machine, its own work).
    const bool gpuClock = timer.usesQueries();
    if (gpuClock)
        timer.start();
    const double runStart = common::processCpuMilliseconds();
    drawRows(renderer, wall::tileRays(wall_, top.screen), target, myScreen ? *own->triangle : *scratch->triangle,
             firstGlRow(bottom, screen.heightPx), bottom.y0 + bottom.height - top.y0);
    if (gpuClock)
        timer.stop();
    double aheadMs = 0.0;
    if (firstOfFrame) {
        gl::glFlush(); // the draw starts now (a CPU rasterizer waits for a flush), not at glFinish
        const double aheadStart = common::processCpuMilliseconds();
        renderer.whileDrawing();
        aheadMs = common::processCpuMilliseconds() - aheadStart;
    }
    gl::glFinish();
    const double runMs = gpuClock ? 1e3 * timer.seconds() : common::processCpuMilliseconds() - runStart - aheadMs;
    if (gpuClock)
        report.renderGpuMs += runMs;

    if (measureCosts_)
        shareRunCost(first, end, target, screen.heightPx, runMs, report, costs);
    if (!myScreen)
        for (size_t i = first; i < end; ++i) {
            const cluster::Band& b = bands_[i];
            outgoing.pixels.push_back(rgbHalves(target.readbackRgb(firstGlRow(b, screen.heightPx), b.height)));
            outgoing.bands.push_back(static_cast<int>(i));
        }
}

void BandFrame::shareRunCost(size_t first, size_t end, const gl::FloatTarget& target, int screenHeight, double runMs,
                             cluster::RankReport& report, std::vector<cluster::BandCost>& costs) const
{
    std::vector<double> work(end - first, 0.0);
    double runWork = 0.0;
    for (size_t i = first; i < end; ++i) {
        for (float w : target.readbackWork(firstGlRow(bands_[i], screenHeight), bands_[i].height))
            work[i - first] += w;
        runWork += work[i - first];
    }
    report.renderWork += runWork;
    for (size_t i = first; i < end; ++i)
        costs.push_back({static_cast<std::int32_t>(i), runWork > 0.0 ? runMs * work[i - first] / runWork : 0.0,
                         work[i - first]});
}

void BandFrame::exchange(const OutgoingBands& outgoing, gl::Context& context, std::vector<ScreenTarget>& screens,
                         const std::vector<std::int32_t>& assignment, const cluster::MpiWorld& world,
                         cluster::RankReport& report) const
{
    const auto exchangeStart = common::SteadyClock::now();
    std::vector<std::vector<std::uint8_t>> outgoingBytes;
    for (const auto& pixels : outgoing.pixels)
        outgoingBytes.push_back(io::compressHalves(pixels, 3));
    std::vector<cluster::MpiWorld::Message> sent, received;
    for (size_t k = 0; k < outgoing.bands.size(); ++k)
        sent.push_back({bands_[outgoing.bands[k]].owner, outgoing.bands[k], &outgoingBytes[k]});
    std::vector<size_t> arrivingBands;
    for (size_t i = 0; i < bands_.size(); ++i)
        if (bands_[i].owner == rank_ && assignment[i] != rank_)
            arrivingBands.push_back(i);
    std::vector<std::vector<std::uint8_t>> incomingBytes(arrivingBands.size());
    for (size_t k = 0; k < arrivingBands.size(); ++k)
        received.push_back({assignment[arrivingBands[k]], static_cast<int>(arrivingBands[k]), &incomingBytes[k]});
    world.exchange(sent, received);
    size_t bytes = 0;
    for (const auto& m : sent)
        bytes += m.bytes->size();
    for (const auto& m : received)
        bytes += m.bytes->size();
    report.exchangeMB = 1e-6 * static_cast<double>(bytes);
    for (size_t k = 0; k < arrivingBands.size(); ++k) {
        const cluster::Band& b = bands_[arrivingBands[k]];
        const std::vector<std::uint16_t> pixels =
            receivedBandPixels(incomingBytes[k], b, static_cast<int>(arrivingBands[k]), wall_.screens[b.screen].widthPx,
                               rank_, assignment[arrivingBands[k]]);
        ScreenTarget& own = screenTarget(screens, b.screen);
        context.makeCurrent(own.window);
        own.target->uploadRgbHalf(firstGlRow(b, wall_.screens[b.screen].heightPx), b.height, pixels);
    }
    context.makeCurrent(0);
    report.exchangeMs = common::millisecondsSince(exchangeStart);
}

} // namespace aurorawall::app
