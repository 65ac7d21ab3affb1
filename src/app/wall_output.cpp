#include "app/wall_output.h"

#include "app/cli/exit_status.h"
#include "io/exr.h"
#include "io/half_pixels.h"
#include "io/image.h"
#include "io/png.h"

#include <cstdint>
#include <cstdio>
#include <cstring>
#include <utility>

namespace aurorawall::app {

namespace {

// Screens travel to the master as half-float RGB (io/half_pixels.h): a header (screen, width, height),
// then the halves.
std::vector<char> packTiles(const std::vector<std::pair<int, io::Image>>& tiles)
{
    std::vector<char> bytes;
    for (const auto& [screen, image] : tiles) {
        const int header[3] = {screen, image.width, image.height};
        const char* h = reinterpret_cast<const char*>(header);
        bytes.insert(bytes.end(), h, h + sizeof header);
        const std::vector<std::uint16_t> rgb = io::packRgbHalf(image);
        const char* p = reinterpret_cast<const char*>(rgb.data());
        bytes.insert(bytes.end(), p, p + rgb.size() * sizeof(std::uint16_t));
    }
    return bytes;
}

io::Image assembleWall(const wall::Wall& wall, const std::vector<char>& bytes)
{
    io::Image canvas(wall.canvasSizePx.x, wall.canvasSizePx.y);
    size_t at = 0;
    while (at < bytes.size()) {
        int header[3];
        std::memcpy(header, bytes.data() + at, sizeof header);
        at += sizeof header;
        std::vector<std::uint16_t> rgb(3 * size_t(header[1]) * header[2]);
        std::memcpy(rgb.data(), bytes.data() + at, rgb.size() * sizeof(std::uint16_t));
        at += rgb.size() * sizeof(std::uint16_t);
        const wall::Screen& screen = wall.screens[header[0]];
        io::pasteTile(canvas, io::unpackRgbHalf(header[1], header[2], rgb), screen.canvasOffsetPx.x,
                      screen.canvasOffsetPx.y);
    }
    // Bezels stay black, as on the wall; alpha 1 everywhere so viewers show them as black, not transparent.
    for (size_t i = 3; i < canvas.rgba.size(); i += 4)
        canvas.rgba[i] = 1.0f;
    return canvas;
}

} // namespace

int writeOutputs(WallSession& session, const cluster::MpiWorld& world, const cluster::FrameStats& stats)
{
    const RenderOptions& options = session.options;
    // Each screen as its target holds it, rounded to half floats (the bands drawn elsewhere arrived
    // as halves already), whoever drew its bands.
    std::vector<std::pair<int, io::Image>> images;
    int status = agreedStep(world, [&] {
        for (ScreenTarget& s : session.screens) {
            session.context->makeCurrent(s.window);
            images.emplace_back(s.screen, io::roundedToHalf(io::imageFromGlReadback(
                                              s.target->width(), s.target->height(), s.target->readback())));
            if (options.tiles)
                io::writeExr(options.outDir + "/tile-" + session.wall.screens[s.screen].name + ".exr",
                             images.back().second);
        }
        session.context->makeCurrent(0);
    });
    std::vector<char> gathered;
    if (status == cli::kSuccess && options.gather) {
        std::vector<int> sizes;
        gathered = world.gatherBytes(packTiles(images), sizes);
    }
    if (status == cli::kSuccess)
        status = agreedStep(world, [&] {
            if (!world.isMaster())
                return;
            if (options.gather) {
                const io::Image canvas = assembleWall(session.wall, gathered);
                io::writeExr(options.outDir + "/wall.exr", canvas);
                io::writePng(options.outDir + "/wall.png", canvas, session.toneMap);
            }
            if (!options.statsFile.empty())
                stats.write(options.statsFile);
        });
    if (world.isMaster()) {
        std::printf("%s\n", stats.summary().c_str());
        if (status == cli::kSuccess && options.gather)
            std::printf("wrote %s/wall.exr and %s/wall.png\n", options.outDir.c_str(), options.outDir.c_str());
    }
    return status;
}

} // namespace aurorawall::app
