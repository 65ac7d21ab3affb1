#include "app/wall_session.h"

#include "app/wall_output.h"
#include "cli/exit_status.h"
#include "cluster/rank_groups.h"
#include "components/registry.h"
#include "common/data_dir.h"
#include "common/formatted.h"
#include "common/input_error.h"
#include "io/directory.h"
#include "render/march_shader.h"
#include "wall/wall_file.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <iostream>

#include <unistd.h>

namespace aurorawall::app {

namespace {

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

// A path made absolute, with its links and dots resolved as far as it exists and no trailing separator.
std::filesystem::path resolvedPath(const std::string& path)
{
    std::error_code error;
    const std::filesystem::path absolute = std::filesystem::absolute(path, error);
    const std::filesystem::path resolved = std::filesystem::weakly_canonical(absolute, error);
    const std::filesystem::path result = error ? absolute.lexically_normal() : resolved;
    return result.has_filename() || !result.has_relative_path() ? result : result.parent_path();
}

// A file the run writes (README.md, "Outputs"): its path, the option that asks for it and the rank that
// writes it.
struct OutputFile {
    std::string path;
    const char* option;
    int rank;
};

// Whether the run writes into --out: the wall, the tiles, or the screenshots the control commands take.
bool writesOutFolder(const RenderOptions& options)
{
    return options.gather || options.tiles || options.controlPort >= 0 || options.webPort >= 0;
}

std::vector<OutputFile> outputFiles(const RenderOptions& options, const wall::Wall& wall)
{
    std::vector<OutputFile> files;
    for (const auto& [path, option] : {std::pair{options.statsFile, "--stats"}, std::pair{options.recordPath, "--record-path"},
                                       std::pair{options.costMapFile, "--cost-map"}})
        if (!path.empty())
            files.push_back({path, option, 0});
    if (options.gather)
        for (const char* name : {"/wall.exr", "/wall.png"})
            files.push_back({options.outDir + name, "--gather", 0});
    if (options.tiles) // each rank writes its own screens' tiles
        for (const wall::Screen& screen : wall.screens)
            files.push_back({tilePath(options.outDir, screen.name), "--tiles", screen.rank});
    return files;
}

// Two outputs at one path, an output at the path of an input or of an output folder, or an output among
// the files of the --movie folder would write one over the other: a usage error naming both, before
// anything is written.
void refuseClashingPaths(const std::vector<OutputFile>& outputs, const RenderOptions& options,
                         const scene::Scene& scene)
{
    struct Input {
        std::string path;
        std::string what;
        std::filesystem::path resolved;
    };
    std::vector<Input> inputs = {{options.wallFile, "the --wall file", resolvedPath(options.wallFile)},
                                 {options.sceneFile, "the --scene file", resolvedPath(options.sceneFile)}};
    for (const std::string& file : scene.baseFiles)
        inputs.push_back({file, "a base scene of --scene", resolvedPath(file)});
    if (!options.controlTokenFile.empty())
        inputs.push_back({options.controlTokenFile, "the --control-token-file", resolvedPath(options.controlTokenFile)});
    const std::filesystem::path movie = options.movieDir.empty() ? std::filesystem::path() : resolvedPath(options.movieDir);
    std::vector<Input> folders;
    if (writesOutFolder(options))
        folders.push_back({options.outDir, "--out", resolvedPath(options.outDir)});
    if (!movie.empty())
        folders.push_back({options.movieDir, "--movie", movie});
    std::vector<std::filesystem::path> resolved;
    for (const OutputFile& out : outputs) {
        resolved.push_back(resolvedPath(out.path));
        const std::string named = std::string(out.option) + " " + out.path;
        for (const Input& folder : folders)
            if (folder.resolved == resolved.back())
                throw common::UsageError(named + " is the " + folder.what + " folder: give them different paths");
        for (std::size_t j = 0; j + 1 < resolved.size(); ++j)
            if (resolved[j] == resolved.back())
                throw common::UsageError(named + " is the file of " + outputs[j].option + " " + outputs[j].path +
                                         ": give them different paths");
        for (const Input& in : inputs)
            if (in.resolved == resolved.back())
                throw common::UsageError(named + " would overwrite " + in.what + " (" + in.path + "): give another path");
        if (!movie.empty() && resolved.back().parent_path() == movie &&
            MovieWriter::writes(resolved.back().filename().string()))
            throw common::UsageError(named + " is a file the --movie folder's frames write: give another path");
    }
}

// The options that assemble the whole wall canvas on rank 0 need it in memory there, with its encodings
// and the gathered tiles: about 32 bytes a pixel (float RGB 12, the tiles as half floats 6, the EXR's
// 6, the PNG's 3, the cost map's work and owner 12 at most). A canvas beyond the master's memory is
// refused before the first frame, naming the option, instead of failing to allocate after it.
void refuseCanvasBeyondMemory(const RenderOptions& options, const wall::Wall& wall)
{
    const char* option = options.gather            ? "--gather"
                         : !options.movieDir.empty() ? "--movie"
                         : !options.costMapFile.empty() ? "--cost-map"
                                                        : nullptr;
    if (!option)
        return;
    constexpr double kBytesPerPixel = 32.0, kGiB = 1024.0 * 1024.0 * 1024.0;
    const double needed = kBytesPerPixel * double(wall.canvasSizePx.x) * double(wall.canvasSizePx.y);
    const double memory = double(sysconf(_SC_PHYS_PAGES)) * double(sysconf(_SC_PAGESIZE));
    if (memory > 0.0 && needed > memory)
        throw common::InputError(common::formatted("%s: the wall canvas of %dx%d pixels needs about %.1f GiB on rank 0 "
                                                   "(%.0f bytes a pixel), more than its host's %.1f GiB of memory",
                                                   option, wall.canvasSizePx.x, wall.canvasSizePx.y,
                                                   needed / kGiB, kBytesPerPixel, memory / kGiB));
}

// A movie starts in a folder that holds none of a movie's files (MovieWriter::writes), so that it
// overwrites no earlier movie.
void refuseEarlierMovie(const std::string& dir)
{
    std::error_code error;
    for (const std::filesystem::directory_entry& entry : std::filesystem::directory_iterator(dir, error))
        if (MovieWriter::writes(entry.path().filename().string()))
            throw common::InputError("--movie " + dir + ": already holds " + entry.path().filename().string() +
                                     " of a movie; give another folder");
}

// Options, wall, scene, shaders and output folders, identical on every rank.
void configure(const cluster::MpiWorld& world, int argc, char** argv, WallSession& s)
{
    RenderOptions& options = s.options;
    options = parseRenderOptions(argc, argv);
    if (options.help)
        return;
    s.wall = wall::loadWall(options.wallFile);
    if (options.singleScreen)
        s.wall = wall::singleScreenEquivalent(s.wall);
    if (options.printRanks)
        return;
    if (s.wall.rankCount != world.size())
        throw common::UsageError(options.wallFile + (options.singleScreen ? " with --single-screen" : "") +
                         ": the wall is driven by " + std::to_string(s.wall.rankCount) +
                         (s.wall.rankCount == 1 ? " rank" : " ranks") + ", but mpirun started " +
                         std::to_string(world.size()) + " (use mpirun -n " + std::to_string(s.wall.rankCount) + ")");
    s.scene = components::loadScene(options.sceneFile);
    const std::vector<OutputFile> outputs = outputFiles(options, s.wall);
    refuseClashingPaths(outputs, options, s.scene);
    if (world.isMaster())
        refuseCanvasBeyondMemory(options, s.wall);
    s.dataDir = options.dataDir.empty() ? common::dataDirectory() : options.dataDir;
    s.shaderDir = s.dataDir + "/shaders";
    render::marchShaderSource(s.scene, s.shaderDir); // every module readable before any window opens
    s.exposure = options.exposure > 0 ? options.exposure : s.scene.exposure;
    s.toneMap = toneMapFor(options, s.exposure);
    s.balanced = options.balance == Balance::On || (options.balance == Balance::Auto && world.size() > 1);
    s.bands = cluster::makeBands(s.wall, s.balanced ? options.balanceBands : 1);
    if (world.isMaster() && options.controlPort >= 0)
        s.control = std::make_unique<control::ControlServer>(options.controlBind, options.controlPort,
                                                             control::readControlToken(options.controlTokenFile));
    if (world.isMaster() && options.webPort >= 0) {
        web::WebSettings settings;
        settings.bindAddress = options.controlBind;
        settings.port = options.webPort;
        settings.token = control::readControlToken(options.controlTokenFile);
        settings.pageDir = s.dataDir + "/web";
        settings.presetDir = s.dataDir + "/config/scenes";
        settings.toneMap = s.toneMap;
        // The web server's thread asks for them once a frame has been drawn, after the watchdog started;
        // the session, and so the server, ends before the world.
        settings.heartbeatAgesS = [&world] { return world.heartbeatAgesS(); };
        settings.heartbeatPeriodS = cluster::heartbeatPeriodS(options.rankTimeoutS);
        s.web = std::make_unique<web::WebConsole>(std::move(settings));
    }
}

// The output folders, made once every rank has accepted the run (configure), so that a run one rank
// refuses leaves no folder behind; then each rank checks the files it writes before any frame, so
// that no run's data is lost to a path that cannot be written (README.md, "Outputs").
void prepareOutputs(const cluster::MpiWorld& world, const WallSession& s)
{
    const RenderOptions& options = s.options;
    if (writesOutFolder(options))
        io::ensureWritableDirectory(options.outDir, "--out");
    if (!options.movieDir.empty()) {
        io::ensureWritableDirectory(options.movieDir, "--movie");
        refuseEarlierMovie(options.movieDir);
    }
    for (const OutputFile& file : outputFiles(options, s.wall))
        if (file.rank == world.rank())
            io::ensureWritableFile(file.path, file.option);
}

// A context per rank (a window per screen with glfw), the raymarcher, the screens' targets.
void openGraphics(const cluster::MpiWorld& world, WallSession& s)
{
    const gl::Backend backend = s.options.backend;
    const std::vector<int> myScreens = s.wall.screensOfRank(world.rank());
    std::vector<gl::WindowSpec> windows = windowsFor(s.wall, myScreens);
    const bool console = s.options.console && world.isMaster();
    if (console) {
        gl::WindowSpec spec;
        spec.title = "aurorawall console";
        spec.widthPx = kConsoleWidthPx;
        spec.heightPx = consoleHeightPx(s.wall.canvasSizePx.x, s.wall.canvasSizePx.y);
        const glm::ivec2 position = consolePositionPx(s.wall);
        spec.x = position.x;
        spec.y = position.y;
        windows.push_back(spec);
    }
    s.context = gl::createContext(backend, windows, world.nodeRank());
    // A screen beyond the device's render targets would fail at its framebuffer ("incomplete, status
    // 36054"); name the wall file's key instead, before anything is drawn or written. Ranks with the
    // same device and screen size give the same line, which the agreed error prints once.
    const int largestPx = gl::largestRenderTargetPx();
    for (int screenIndex : myScreens) {
        const wall::Screen& screen = s.wall.screens[screenIndex];
        for (const auto& [key, px] : {std::pair{"width_px", screen.widthPx}, std::pair{"height_px", screen.heightPx}})
            if (px > largestPx)
                throw common::InputError(s.options.wallFile + (s.options.singleScreen ? " with --single-screen" : "") + ": " +
                                 key + " = " + std::to_string(px) + " is more than this GL device's largest render target, " +
                                 std::to_string(largestPx) +
                                 " px (the least of GL_MAX_TEXTURE_SIZE, GL_MAX_RENDERBUFFER_SIZE and GL_MAX_VIEWPORT_DIMS)");
    }
    const render::MarchStage stage = s.options.march == MarchChoice::Compute    ? render::MarchStage::Compute
                                     : s.options.march == MarchChoice::Fragment ? render::MarchStage::Fragment
                                                                                : render::preferredMarchStage(s.context->rendererName());
    // The cost map measures each pixel's time with the GPU's clock where it has one, else counts its
    // texture fetches (render/work_counts.h). Mesa's CPU renderers have a shader clock, but it is the
    // CPU's time stamp, which counts whatever the operating system ran meanwhile.
    const bool gpuClock = gl::hasExtension("GL_ARB_shader_clock") && !gl::isSoftwareRenderer(s.context->rendererName());
    const render::PixelWork pixelWork = s.options.costMapFile.empty() ? render::PixelWork::Samples
                                        : gpuClock                    ? render::PixelWork::ShaderClock
                                                                      : render::PixelWork::TextureFetches;
    s.renderer = std::make_unique<render::TileRenderer>(s.scene, s.shaderDir, stage, render::CountWork::No, pixelWork);
    if (backend == gl::Backend::Glfw)
        s.presenter = std::make_unique<render::WindowPresenter>(s.shaderDir, s.toneMap);
    for (size_t i = 0; i < myScreens.size(); ++i) {
        ScreenTarget screen;
        screen.screen = myScreens[i];
        screen.window = backend == gl::Backend::Glfw ? static_cast<int>(i) : 0;
        s.context->makeCurrent(screen.window);
        const wall::Screen& physical = s.wall.screens[screen.screen];
        screen.target = std::make_unique<gl::FloatTarget>(physical.widthPx, physical.heightPx);
        screen.triangle = std::make_unique<gl::FullScreenTriangle>();
        screen.drawTimer = std::make_unique<gl::GpuTimer>();
        s.screens.push_back(std::move(screen));
    }
    if (console) {
        s.console = std::make_unique<ConsoleView>();
        s.console->window = static_cast<int>(myScreens.size());
        s.context->makeCurrent(s.console->window);
        const gl::WindowSpec& spec = windows.back();
        s.console->image = std::make_unique<gl::Texture>(gl::Texture::create2D(
            spec.widthPx, spec.heightPx, gl::TexelFormat::RGBA32F, gl::Filter::Nearest, gl::Wrap::Clamp));
        s.console->triangle = std::make_unique<gl::FullScreenTriangle>();
    }
    s.context->makeCurrent(0);
}

// Every rank's GL device, named on the master. Tiles drawn on different devices can differ in the last
// bits at their seams (each device rounds its own way), and a rank left on a software device is slow:
// a wall whose ranks differ is warned of, on stderr; --verbose lists the devices in any case.
void reportDevices(const cluster::MpiWorld& world, const WallSession& s)
{
    const std::string mine = s.context->rendererName();
    const std::vector<std::string> devices = world.gatherStrings(mine);
    if (!world.isMaster())
        return;
    const bool mixed = std::any_of(devices.begin(), devices.end(), [&](const std::string& d) { return d != mine; });
    if (mixed)
        std::fprintf(stderr, "aurorawall: warning: the ranks draw on different GL devices: %s; their tiles can "
                             "differ in the last bits at the seams\n",
                     cluster::ranksByValue(devices).c_str());
    else if (s.options.verbose)
        std::printf("devices: %s\n", cluster::ranksByValue(devices).c_str());
    std::fflush(stdout);
}

} // namespace

int agreedStep(const cluster::MpiWorld& world, const std::function<void()>& step)
{
    int status = cli::kSuccess;
    std::string error;
    try {
        step();
    } catch (const std::exception& e) {
        status = cli::exitStatusOf(e);
        error = e.what();
        if (error.empty())
            error = "unknown error";
    }
    return world.agreedStatus(status, error, "aurorawall render");
}

int setUpWallSession(const cluster::MpiWorld& world, int argc, char** argv, WallSession& session)
{
    int status = agreedStep(world, [&] { configure(world, argc, argv, session); });
    if (status != cli::kSuccess)
        return status;
    if (session.options.help || session.options.printRanks) {
        if (!world.isMaster())
            return cli::kSuccess;
        if (session.options.help)
            std::cout << session.options.helpText;
        else
            std::cout << session.wall.rankCount << "\n";
        std::cout.flush();
        if (std::cout)
            return cli::kSuccess;
        std::fprintf(stderr, "%s\n", cli::errorLine("render", "cannot write the output").c_str());
        return cli::kRuntimeFailure;
    }
    status = agreedStep(world, [&] { prepareOutputs(world, session); });
    if (status != cli::kSuccess)
        return status;
    world.startWatchdog(session.options.rankTimeoutS);
    world.setPhase(cluster::RankPhase::SetUp);
    if (session.options.verbose) { // lets an operator (or a test) find a rank's process
        std::printf("rank %d: pid %d\n", world.rank(), static_cast<int>(getpid()));
        std::fflush(stdout);
    }
    status = agreedStep(world, [&] { openGraphics(world, session); });
    if (status != cli::kSuccess)
        return status;
    reportDevices(world, session);
    if (session.control) { // printed even with --quiet: with port 0 it is how a client learns the port
        std::printf("control: listening on %s:%d\n", session.control->address().c_str(), session.control->port());
        std::fflush(stdout);
    }
    if (session.web) { // the same, for the browser console
        std::printf("web: listening on %s:%d\n", session.web->address().c_str(), session.web->port());
        std::fflush(stdout);
    }
    if (world.isMaster() && !session.options.quiet) {
        std::printf("aurorawall: %d ranks, %zu screens, canvas %dx%d, backend %s on %s (vendor %s, OpenGL %s), "
                    "march as a %s shader\n",
                    world.size(), session.wall.screens.size(), session.wall.canvasSizePx.x,
                    session.wall.canvasSizePx.y, gl::backendName(session.options.backend).c_str(),
                    session.context->rendererName().c_str(), session.context->vendorName().c_str(),
                    session.context->glVersion().c_str(),
                    session.renderer->stage() == render::MarchStage::Compute ? "compute" : "fragment");
        if (session.renderer->pixelWork() != render::PixelWork::Samples)
            std::printf("cost map: each pixel's %s\n", session.renderer->pixelWork() == render::PixelWork::ShaderClock
                                                            ? "time on the GPU clock (GL_ARB_shader_clock)"
                                                            : "texture fetches (no GPU clock)");
        for (const std::string& line : session.renderer->precomputationLog())
            std::printf("precomputed %s\n", line.c_str());
    }
    return cli::kSuccess;
}

} // namespace aurorawall::app
