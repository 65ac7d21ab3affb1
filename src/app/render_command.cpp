#include "app/render_command.h"

#include "app/balanced_frame.h"
#include "app/cli/exit_status.h"
#include "app/render_options.h"
#include "cluster/load_balancer.h"
#include "cluster/frame_stats.h"
#include "cluster/master_clock.h"
#include "cluster/mpi_world.h"
#include "common/clock.h"
#include "common/data_dir.h"
#include "common/input_error.h"
#include "gl/context.h"
#include "gl/float_target.h"
#include "gl/functions.h"
#include "io/directory.h"
#include "io/exr.h"
#include "io/half_pixels.h"
#include "io/image.h"
#include "io/png.h"
#include "render/fragment_shader.h"
#include "render/tile_renderer.h"
#include "render/window_presenter.h"
#include "components/registry.h"
#include "scene/scene.h"
#include "wall/tile_rays.h"
#include "wall/wall_file.h"

#include <chrono>
#include <filesystem>
#include <cstdio>
#include <cstdint>
#include <cstring>
#include <functional>
#include <iostream>
#include <memory>
#include <optional>

namespace aurorawall::app {

namespace {

// Runs one set-up step on every rank and agrees on its outcome: returns the largest exit status
// over the ranks (app/cli/exit_status.h; 0 if no rank threw), on every rank (rank 0 has printed
// the reasons).
int setUpStep(const cluster::MpiWorld& world, const std::function<void()>& step)
{
    std::string error;
    int status = cli::kSuccess;
    try {
        step();
    } catch (const std::exception& e) {
        error = e.what();
        if (error.empty())
            error = "unknown error";
        status = cli::exitStatusOf(e);
    }
    return world.agreedStatus(status, error, "aurorawall render");
}

// One screen this rank draws: where its pixels come from and where they go.
struct Tile {
    int screenIndex = 0;
    int window = 0; // context/window it is drawn in (glfw: one per screen; headless: 0)
    wall::TileRays rays;
    std::unique_ptr<gl::FloatTarget> target;
    std::unique_ptr<gl::FullScreenTriangle> triangle;
};

std::vector<gl::WindowSpec> windowsFor(const wall::Wall& wall, const std::vector<int>& screens)
{
    std::vector<gl::WindowSpec> windows;
    for (int s : screens) {
        const wall::Screen& screen = wall.screens[s];
        gl::WindowSpec w;
        w.title = "aurorawall " + screen.name;
        w.widthPx = screen.window.width > 0 ? screen.window.width : screen.widthPx;
        w.heightPx = screen.window.height > 0 ? screen.window.height : screen.heightPx;
        w.x = screen.window.x;
        w.y = screen.window.y;
        w.monitor = screen.window.monitor;
        w.fullscreen = screen.window.fullscreen;
        windows.push_back(w);
    }
    return windows;
}

io::ToneMap toneMapFor(const RenderOptions& options, double exposure)
{
    io::ToneMap t;
    t.curve = options.toneMap;
    t.exposure = exposure;
    return t;
}

// Puts a top-down CPU image into a float target's texture (GL rows run bottom-up).
void uploadToTarget(const io::Image& image, gl::FloatTarget& target)
{
    std::vector<float> texels(image.rgba.size());
    const size_t row = 4 * size_t(image.width);
    for (int y = 0; y < image.height; ++y)
        std::copy_n(&image.rgba[size_t(image.height - 1 - y) * row], row, &texels[size_t(y) * row]);
    target.texture().upload(texels);
}

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

int runRenderCommand(int argc, char** argv)
{
    cluster::MpiWorld world(&argc, &argv);

    // 1. Configuration, identical on every rank: options, wall, scene, shaders, output folder.
    RenderOptions options;
    wall::Wall wallLayout;
    scene::Scene scene;
    std::vector<int> myScreens;
    std::string shaderDir;
    const int configured = setUpStep(world, [&] {
        options = parseRenderOptions(argc, argv);
        if (options.help)
            return;
        wallLayout = wall::loadWall(options.wallFile);
        if (options.singleScreen)
            wallLayout = wall::singleScreenEquivalent(wallLayout);
        if (wallLayout.rankCount != world.size())
            throw UsageError(options.wallFile + (options.singleScreen ? " with --single-screen" : "") +
                             ": the wall is driven by " + std::to_string(wallLayout.rankCount) +
                             (wallLayout.rankCount == 1 ? " rank" : " ranks") + ", but mpirun started " +
                             std::to_string(world.size()) + " (use mpirun -n " + std::to_string(wallLayout.rankCount) +
                             ")");
        scene = components::loadScene(options.sceneFile);
        shaderDir = (options.dataDir.empty() ? dataDirectory() : options.dataDir) + "/shaders";
        render::fragmentShaderSource(scene, shaderDir); // every module readable before any window opens
        if (options.gather || options.tiles)
            io::ensureWritableDirectory(options.outDir, "--out");
        if (!options.statsFile.empty()) {
            const std::filesystem::path parent = std::filesystem::path(options.statsFile).parent_path();
            io::ensureWritableDirectory(parent.empty() ? "." : parent.string(), "--stats");
        }
        myScreens = wallLayout.screensOfRank(world.rank());
    });
    if (configured != cli::kSuccess)
        return configured;
    if (options.help) {
        if (world.isMaster())
            std::cout << options.helpText;
        return 0;
    }

    // 2. Graphics: a context (and windows) per rank, the raymarcher compiled for this scene.
    const gl::Backend backend = options.backend;
    std::unique_ptr<gl::Context> context;
    std::unique_ptr<render::TileRenderer> renderer;
    std::unique_ptr<render::WindowPresenter> presenter;
    std::vector<Tile> tiles;
    const double exposure = options.exposure > 0 ? options.exposure : scene.exposure;
    const int graphicsReady = setUpStep(world, [&] {
        context = gl::createContext(backend, windowsFor(wallLayout, myScreens));
        renderer = std::make_unique<render::TileRenderer>(scene, shaderDir);
        if (backend == gl::Backend::Glfw)
            presenter = std::make_unique<render::WindowPresenter>(shaderDir, toneMapFor(options, exposure));
        for (size_t i = 0; i < myScreens.size(); ++i) {
            Tile tile;
            tile.screenIndex = myScreens[i];
            tile.window = backend == gl::Backend::Glfw ? static_cast<int>(i) : 0;
            context->makeCurrent(tile.window);
            const wall::Screen& screen = wallLayout.screens[tile.screenIndex];
            tile.rays = wall::tileRays(wallLayout, tile.screenIndex);
            tile.target = std::make_unique<gl::FloatTarget>(screen.widthPx, screen.heightPx);
            tile.triangle = std::make_unique<gl::FullScreenTriangle>();
            tiles.push_back(std::move(tile));
        }
    });
    if (graphicsReady != cli::kSuccess)
        return graphicsReady;

    // Load balancing: the master splits the bands, every rank renders its share.
    std::vector<int> assignment;
    std::unique_ptr<BalancedFrame> balanced;
    std::unique_ptr<cluster::LoadBalancer> balancer;
    const BandMeasure bandMeasure = options.balanceBy;
    if (options.balance == Balance::On || (options.balance == Balance::Auto && world.size() > 1)) {
        std::vector<cluster::Band> bands = cluster::makeBands(wallLayout, options.balanceBands);
        assignment.resize(bands.size());
        if (world.isMaster())
            balancer = std::make_unique<cluster::LoadBalancer>(bands, world.size());
        balanced = std::make_unique<BalancedFrame>(wallLayout, std::move(bands), world.rank());
    }
    if (world.isMaster() && !options.quiet) {
        std::printf("aurorawall: %d ranks, %zu screens, canvas %dx%d, backend %s on %s\n", world.size(),
                    wallLayout.screens.size(), wallLayout.canvasSizePx.x, wallLayout.canvasSizePx.y,
                    gl::backendName(options.backend).c_str(), context->rendererName().c_str());
        for (const std::string& line : renderer->precomputationLog())
            std::printf("precomputed %s\n", line.c_str());
    }

    // 3. The frame loop: the master decides, everyone renders, all flip together.
    cluster::ClockSettings clockSettings;
    clockSettings.frames = static_cast<std::uint64_t>(options.frames);
    clockSettings.startTimeS = options.startTimeGiven ? options.startTimeS : scene.startTimeS;
    clockSettings.timeStepS = options.timeStepS >= 0 ? options.timeStepS : scene.timeStepS;
    clockSettings.realTime = options.realTime;
    std::optional<cluster::MasterClock> clock;
    if (world.isMaster())
        clock.emplace(clockSettings, scene.camera, exposure);
    double pixelsPerFrame = 0;
    for (const wall::Screen& s : wallLayout.screens)
        pixelsPerFrame += double(s.widthPx) * s.heightPx;
    cluster::FrameStats stats(pixelsPerFrame);
    bool stopRequested = false;
    cluster::FrameState frame;
    while (true) {
        const auto frameStart = SteadyClock::now();
        if (world.isMaster())
            frame = clock->next(stopRequested);
        world.broadcast(frame);
        if (frame.quit)
            break;

        cluster::RankReport report{frame.frame, frame.timeS};
        auto phase = SteadyClock::now();
        const double prepareCpuStart = processCpuMilliseconds();
        context->makeCurrent(0);
        renderer->setFrame(frame);
        report.prepareMs = millisecondsSince(phase);
        report.prepareCpuMs = processCpuMilliseconds() - prepareCpuStart;
        if (balanced) {
            if (world.isMaster())
                assignment = balancer->assign();
            world.broadcast(assignment);
            BalancedFrame::Timing timing;
            const std::vector<BandCost> costs = balanced->render(*renderer, assignment, world, timing);
            report.renderMs = timing.renderMs;
            report.renderCpuMs = timing.renderCpuMs;
            report.exchangeMs = timing.exchangeMs;
            report.exchangeMB = timing.exchangeMB;
            report.renderWork = timing.renderWork;
            std::vector<int> sizes;
            const std::vector<char> all = world.gatherBytes(packBandCosts(costs), sizes);
            if (world.isMaster())
                balancer->observe(unpackBandCosts(all, assignment.size(), bandMeasure));
            if (presenter)
                for (Tile& tile : tiles) {
                    context->makeCurrent(tile.window);
                    uploadToTarget(balanced->screenImage(tile.screenIndex), *tile.target);
                }
        } else {
            phase = SteadyClock::now();
            const double cpuStart = processCpuMilliseconds();
            for (Tile& tile : tiles) {
                context->makeCurrent(tile.window);
                renderer->renderTile(tile.rays, *tile.target, *tile.triangle);
            }
            for (Tile& tile : tiles) {
                context->makeCurrent(tile.window);
                gl::glFinish();
            }
            report.renderMs = millisecondsSince(phase);
            report.renderCpuMs = processCpuMilliseconds() - cpuStart;
        }

        phase = SteadyClock::now();
        if (presenter)
            for (Tile& tile : tiles)
                presenter->present(*context, tile.window, *tile.target, *tile.triangle);
        world.swapBarrier();
        report.waitMs = millisecondsSince(phase);
        phase = SteadyClock::now();
        if (presenter) {
            for (Tile& tile : tiles)
                context->swapBuffers(tile.window);
            context->pollEvents();
            report.closeRequested = context->closeRequested();
        }
        report.swapMs = millisecondsSince(phase);

        // The master learns what every rank drew and how long it took, and whether to stop.
        const std::vector<cluster::RankReport> reports = world.gatherReports(report);
        if (world.isMaster()) {
            for (const cluster::RankReport& r : reports)
                stopRequested = stopRequested || r.closeRequested;
            cluster::FrameRecord record{frame.frame, frame.timeS, millisecondsSince(frameStart), reports};
            if (!options.quiet)
                std::printf("%s\n", stats.frameLine(record).c_str());
            if (options.verbose)
                std::printf("  %s\n", renderer->frameLog().c_str());
            stats.add(std::move(record));
        }
    }

    // 4. Output of the last frame: tiles from every rank, the assembled wall from the master.
    std::vector<std::pair<int, io::Image>> images;
    int status = setUpStep(world, [&] {
        for (Tile& tile : tiles) {
            context->makeCurrent(tile.window);
            if (balanced)
                images.emplace_back(tile.screenIndex, balanced->screenImage(tile.screenIndex));
            else
                images.emplace_back(tile.screenIndex,
                                    io::roundedToHalf(io::imageFromGlReadback(
                                        tile.target->width(), tile.target->height(), tile.target->readback())));
            if (options.tiles)
                io::writeExr(options.outDir + "/tile-" + wallLayout.screens[tile.screenIndex].name + ".exr",
                             images.back().second);
        }
    });
    std::vector<char> gathered;
    if (status == cli::kSuccess && options.gather) {
        std::vector<int> sizes;
        gathered = world.gatherBytes(packTiles(images), sizes);
    }
    if (status == cli::kSuccess)
        status = setUpStep(world, [&] {
            if (!world.isMaster())
                return;
            if (options.gather) {
                const io::Image canvas = assembleWall(wallLayout, gathered);
                io::writeExr(options.outDir + "/wall.exr", canvas);
                io::writePng(options.outDir + "/wall.png", canvas, toneMapFor(options, exposure));
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
