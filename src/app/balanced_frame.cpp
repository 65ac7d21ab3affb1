#include "app/balanced_frame.h"

#include "common/clock.h"
#include "gl/functions.h"
#include "io/half_pixels.h"
#include "wall/tile_rays.h"

#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>

namespace aurorawall::app {

BalancedFrame::BalancedFrame(const wall::Wall& wall, std::vector<cluster::Band> bands, int rank)
    : wall_(wall), bands_(std::move(bands)), rank_(rank)
{
    for (int s : wall.screensOfRank(rank))
        screens_.emplace(s, io::Image(wall.screens[s].widthPx, wall.screens[s].heightPx));
}

BalancedFrame::Target& BalancedFrame::targetFor(int width, int height)
{
    Target& t = targets_[{width, height}];
    if (!t.target) {
        t.target = std::make_unique<gl::FloatTarget>(width, height);
        t.triangle = std::make_unique<gl::FullScreenTriangle>();
    }
    return t;
}

std::vector<BandCost> BalancedFrame::render(render::TileRenderer& renderer, const std::vector<int>& assignment,
                                            const cluster::MpiWorld& world, Timing& timing)
{
    // 1. Draw my bands: each run of consecutive bands of one screen in one draw (a draw has a fixed
    // cost, and rasterizers shade whole pixel blocks), its process CPU time split among the run's
    // bands in proportion to their pixels' work (the alpha main.frag writes). Every band, kept or
    // sent, becomes half-float RGB (io/half_pixels.h), so the screen does not depend on who drew it.
    std::vector<BandCost> costs;
    std::vector<std::vector<std::uint16_t>> outgoingPixels;
    std::vector<cluster::MpiWorld::Message> outgoing, incoming;
    const auto start = SteadyClock::now();
    const double cpuStart = processCpuMilliseconds();
    for (size_t first = 0; first < bands_.size();) {
        if (assignment[first] != rank_) {
            ++first;
            continue;
        }
        size_t end = first + 1;
        while (end < bands_.size() && assignment[end] == rank_ && bands_[end].screen == bands_[first].screen)
            ++end;
        const cluster::Band& top = bands_[first];
        const int width = wall_.screens[top.screen].widthPx;
        const int height = bands_[end - 1].y0 + bands_[end - 1].height - top.y0;
        Target& t = targetFor(width, height);
        const double runStart = processCpuMilliseconds();
        renderer.renderTile(wall::tileRays(wall_, top.screen, {0, top.y0}), *t.target, *t.triangle);
        const io::Image run = io::imageFromGlReadback(width, height, t.target->readback());
        const double runMs = processCpuMilliseconds() - runStart;

        std::vector<double> work(end - first, 0.0);
        double runWork = 0.0;
        for (size_t i = first; i < end; ++i) {
            for (int y = bands_[i].y0 - top.y0; y < bands_[i].y0 - top.y0 + bands_[i].height; ++y)
                for (int x = 0; x < width; ++x)
                    work[i - first] += run.pixel(x, y)[3];
            runWork += work[i - first];
        }
        timing.renderWork += runWork;
        for (size_t i = first; i < end; ++i) {
            const cluster::Band& b = bands_[i];
            costs.push_back({static_cast<int>(i), runWork > 0.0 ? runMs * work[i - first] / runWork : 0.0, work[i - first]});
            std::vector<std::uint16_t> pixels = io::packRgbHalf(io::crop(run, 0, b.y0 - top.y0, width, b.height));
            if (b.owner == rank_) {
                io::pasteTile(screens_.at(b.screen), io::unpackRgbHalf(width, b.height, pixels), 0, b.y0);
            } else {
                outgoingPixels.push_back(std::move(pixels));
                outgoing.push_back({b.owner, static_cast<int>(i), nullptr});
            }
        }
        first = end;
    }
    for (size_t k = 0; k < outgoing.size(); ++k)
        outgoing[k].values = &outgoingPixels[k];
    timing.renderMs = millisecondsSince(start);
    timing.renderCpuMs = processCpuMilliseconds() - cpuStart;

    // 2. Exchange: my screens' bands drawn elsewhere come in, other screens' bands go out.
    const auto exchangeStart = SteadyClock::now();
    std::vector<std::pair<int, std::vector<std::uint16_t>>> arriving;
    for (size_t i = 0; i < bands_.size(); ++i)
        if (bands_[i].owner == rank_ && assignment[i] != rank_)
            arriving.emplace_back(static_cast<int>(i), std::vector<std::uint16_t>(
                                                           3 * size_t(wall_.screens[bands_[i].screen].widthPx) *
                                                           bands_[i].height));
    for (auto& [band, pixels] : arriving)
        incoming.push_back({assignment[band], band, &pixels});
    world.exchange(outgoing, incoming);
    size_t words = 0;
    for (const auto& m : outgoing)
        words += m.values->size();
    for (const auto& m : incoming)
        words += m.values->size();
    timing.exchangeMB = 1e-6 * static_cast<double>(words * sizeof(std::uint16_t));
    for (const auto& [band, pixels] : arriving) {
        const cluster::Band& b = bands_[band];
        io::pasteTile(screens_.at(b.screen), io::unpackRgbHalf(wall_.screens[b.screen].widthPx, b.height, pixels), 0,
                      b.y0);
    }
    timing.exchangeMs = millisecondsSince(exchangeStart);
    return costs;
}

std::vector<char> packBandCosts(const std::vector<BandCost>& costs)
{
    std::vector<char> bytes(costs.size() * sizeof(BandCost));
    if (!costs.empty())
        std::memcpy(bytes.data(), costs.data(), bytes.size());
    return bytes;
}

std::vector<double> unpackBandCosts(const std::vector<char>& bytes, size_t bandCount, BandMeasure measure)
{
    std::vector<double> cost(bandCount, std::numeric_limits<double>::quiet_NaN());
    for (size_t at = 0; at + sizeof(BandCost) <= bytes.size(); at += sizeof(BandCost)) {
        BandCost c;
        std::memcpy(&c, bytes.data() + at, sizeof c);
        cost[static_cast<size_t>(c.band)] = measure == BandMeasure::Work ? c.work : c.cpuMs;
    }
    return cost;
}

} // namespace aurorawall::app
