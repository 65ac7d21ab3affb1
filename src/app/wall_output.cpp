#include "app/wall_output.h"

#include "cli/exit_status.h"
#include "app/cost_map.h"
#include "io/atomic_file.h"
#include "io/exr.h"
#include "io/half_pixels.h"
#include "io/image.h"
#include "io/png.h"

#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <regex>
#include <stdexcept>
#include <utility>

namespace aurorawall::app {

std::string tilePath(const std::string& outDir, const std::string& screenName)
{
    return outDir + "/tile-" + screenName + ".exr";
}

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

// The tile EXR of a screen under its final name, and under the name it is staged as until every
// rank has written its tiles.
std::string tilePath(const WallSession& session, int screen)
{
    return app::tilePath(session.options.outDir, session.wall.screens[screen].name);
}
std::string stagedTilePath(const WallSession& session, int screen)
{
    return session.options.outDir + "/.tile-" + session.wall.screens[screen].name + ".exr.staged";
}

// Each screen as its target holds it, rounded to half floats (the bands drawn elsewhere arrived as
// halves already), whoever drew its bands; with writeTiles also written as tile EXRs: all or none.
// Every rank stages its tiles; only when all have succeeded do they take their final names, else
// the staged ones are removed, and the failure is one line from the master (the reason, the same on
// every rank that failed for it, e.g. a full disk).
int readScreens(WallSession& session, const cluster::MpiWorld& world, bool writeTiles,
                std::vector<std::pair<int, io::Image>>& images)
{
    std::vector<int> staged;
    const int status = agreedStep(world, [&] {
        for (ScreenTarget& s : session.screens) {
            session.context->makeCurrent(s.window);
            images.emplace_back(s.screen, io::roundedToHalf(io::imageFromGlReadback(
                                              s.target->width(), s.target->height(), s.target->readback())));
        }
        session.context->makeCurrent(0);
        if (!writeTiles)
            return;
        for (const auto& [screen, image] : images) {
            errno = 0;
            try {
                io::writeExr(stagedTilePath(session, screen), image);
            } catch (const std::exception& e) {
                // The reason without the file names, which differ from rank to rank: the system's
                // error where there is one (a full disk), else the message's last clause.
                const int error = errno;
                const std::string reason = e.what();
                const size_t clause = reason.rfind(": ");
                throw std::runtime_error(
                    "--tiles: the tiles could not be written into " + session.options.outDir + " (" +
                    (error != 0 ? std::strerror(error)
                                : clause == std::string::npos ? reason : reason.substr(clause + 2)) +
                    ")");
            }
            staged.push_back(screen);
        }
    });
    const int renamed = status != cli::kSuccess ? status : agreedStep(world, [&] {
        for (int screen : staged) {
            std::error_code error;
            std::filesystem::rename(stagedTilePath(session, screen), tilePath(session, screen), error);
            if (error)
                throw std::runtime_error("--tiles: " + tilePath(session, screen) + ": " + error.message());
        }
    });
    for (int screen : staged) {
        std::error_code ignored;
        std::filesystem::remove(stagedTilePath(session, screen), ignored); // the ones not renamed
    }
    return renamed;
}

io::Image gatherScreens(const WallSession& session, const cluster::MpiWorld& world,
                        const std::vector<std::pair<int, io::Image>>& images)
{
    std::vector<int> sizes;
    const std::vector<char> gathered = world.gatherBytes(packTiles(images), sizes);
    return world.isMaster() ? assembleWall(session.wall, gathered) : io::Image();
}

} // namespace

int gatherWallImage(WallSession& session, const cluster::MpiWorld& world, io::Image& canvas)
{
    std::vector<std::pair<int, io::Image>> images;
    const int status = readScreens(session, world, false, images);
    if (status == cli::kSuccess)
        canvas = gatherScreens(session, world, images);
    return status;
}

MovieWriter::MovieWriter(std::string dir, bool exr, io::ToneMap toneMap)
    : dir_(std::move(dir)), exr_(exr), toneMap_(toneMap)
{
}

bool MovieWriter::writes(const std::string& name)
{
    static const std::regex frame(R"(frame-[0-9]{6,20}\.(png|exr))");
    return name == kFramesList || std::regex_match(name, frame);
}

void MovieWriter::write(const io::Image& canvas, const cluster::FrameState& state)
{
    char name[32];
    std::snprintf(name, sizeof name, "/frame-%06llu", static_cast<unsigned long long>(state.frame));
    const std::string stem = dir_ + name;
    io::writePng(stem + ".png", canvas, toneMap_);
    if (exr_)
        io::writeExr(stem + ".exr", canvas);
    char row[64];
    std::snprintf(row, sizeof row, "%llu,%.17g\n", static_cast<unsigned long long>(state.frame), state.timeS);
    csv_ += row;
    io::writeFileAtomically(dir_ + "/" + kFramesList, [&](const std::string& temporary) {
        std::ofstream out(temporary, std::ios::binary);
        out << csv_;
        out.close();
        if (!out)
            throw std::runtime_error(dir_ + "/" + kFramesList + ": write failed (" + std::strerror(errno) + ")");
    });
}

int writeOutputs(WallSession& session, const cluster::MpiWorld& world, const cluster::FrameStats& stats)
{
    const RenderOptions& options = session.options;
    std::vector<std::pair<int, io::Image>> images;
    io::Image canvas;
    int status = cli::kSuccess;
    world.setPhase(cluster::RankPhase::Output);
    if (options.gather || options.tiles)
        status = readScreens(session, world, options.tiles, images);
    if (status == cli::kSuccess && options.gather)
        canvas = gatherScreens(session, world, images);
    if (status == cli::kSuccess)
        status = agreedStep(world, [&] {
            if (!world.isMaster())
                return;
            if (!session.movieError.empty())
                throw std::runtime_error(session.movieError);
            if (!session.recordError.empty())
                throw std::runtime_error(session.recordError);
            if (!session.statsError.empty())
                throw std::runtime_error(session.statsError);
            if (options.gather) {
                io::writeExr(options.outDir + "/wall.exr", canvas);
                io::writePng(options.outDir + "/wall.png", canvas, session.toneMap);
            }
            if (!options.statsFile.empty())
                stats.write(options.statsFile);
        });
    if (status == cli::kSuccess && !options.costMapFile.empty())
        status = writeCostMap(session, world, stats);
    if (world.isMaster()) {
        std::printf("%s\n", stats.summary().c_str());
        if (status == cli::kSuccess && options.gather)
            std::printf("wrote %s/wall.exr and %s/wall.png\n", options.outDir.c_str(), options.outDir.c_str());
    }
    return status;
}

} // namespace aurorawall::app
