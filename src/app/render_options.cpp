#include "app/render_options.h"

#include "app/control/control_server.h"
#include "cli/command_line.h"

#include <cmath>

namespace aurorawall::app {

namespace po = boost::program_options;

namespace {

const cli::Choices<gl::Backend> kBackends = {
    {"egl", gl::Backend::Egl}, {"osmesa", gl::Backend::Osmesa}, {"glfw", gl::Backend::Glfw}};
const cli::Choices<MarchChoice> kMarches = {
    {"auto", MarchChoice::Auto}, {"compute", MarchChoice::Compute}, {"fragment", MarchChoice::Fragment}};
const cli::Choices<io::ToneMap::Curve> kToneMaps = {
    {"aces", io::ToneMap::Curve::AcesFilmic}, {"magnitude-gamma", io::ToneMap::Curve::MagnitudeGamma}};
const cli::Choices<Balance> kBalance = {{"on", Balance::On}, {"off", Balance::Off}, {"auto", Balance::Auto}};
const cli::Choices<cluster::BandMeasure> kBandMeasures = {{"time", cluster::BandMeasure::Time},
                                                          {"work", cluster::BandMeasure::Work}};

// The options of the wall, the scene, the clock and the split of the work.
void describeRenderingOptions(cli::CommandLine& cli, RenderOptions& o)
{
    cli.add()
        ("wall", po::value(&o.wallFile)->required(), "wall file (config/walls/*.toml): screens, bezels, eye, ranks")
        ("scene", po::value(&o.sceneFile)->required(), "scene file (config/scenes/*.toml): components and parameters");
    cli.addChoice("backend", &o.backend, kBackends,
                  "OpenGL backend: egl (headless; GPU or Mesa llvmpipe), osmesa (headless), glfw (one window per screen)");
    cli.addChoice("march", &o.march, kMarches,
                  "shader stage of the raymarcher: compute (8x4-pixel workgroups; on GPUs every multiprocessor "
                  "runs them), fragment (a full-screen triangle), or auto (the faster on this device: fragment "
                  "on Mesa's CPU renderers, compute elsewhere); the same image either way");
    cli.add()
        ("frames", po::value(&o.frames)->default_value(o.frames),
         "number of frames to render; 0 = until a window is closed (glfw) or the wall is told to quit "
         "(--control-port, --web-port)")
        ("dt", po::value(&o.timeStepS), "animation time step per frame in seconds (default: the scene's time_step_s)")
        ("start-time", po::value(&o.startTimeS), "animation time of the first frame in seconds (default: the scene's)")
        ("realtime", po::bool_switch(&o.realTime), "animation time follows the master's wall clock instead of --dt (one frame behind it: each frame shows the moment the one before it began)")
        ("exposure", po::value(&o.exposure), "multiplies radiance for the PNG preview and windows (default: the scene's)");
    cli.addChoice("tonemap", &o.toneMap, kToneMaps,
                  "preview curve: aces (ACES filmic + sRGB) or magnitude-gamma (Lawlor & Genetti)");
    cli.add()
        ("out", po::value(&o.outDir)->default_value(o.outDir), "output folder for images")
        ("gather", po::bool_switch(&o.gather), "rank 0 assembles the whole wall: OUT/wall.exr and OUT/wall.png")
        ("tiles", po::bool_switch(&o.tiles), "every rank writes its tiles: OUT/tile-<screen>.exr (linear, half float)");
    cli.addChoice("balance", &o.balance, kBalance,
                  "dynamic load balancing (auto: on with more than one rank; --balance alone: on): every screen is "
                  "cut into bands, and each frame ranks with cheap screens render bands of expensive ones (split "
                  "from measured costs, damped); the image is unchanged. Costs a readback and a transfer of the "
                  "moved bands per frame",
                  "on");
    cli.add()
        ("balance-bands", po::value(&o.balanceBands)->default_value(o.balanceBands),
         "bands per screen for --balance (1 to 256; at most one per 8 rows)");
    cli.addChoice("balance-by", &o.balanceBy, kBandMeasures,
                  "what --balance equalizes: time (each band's measured time: the GPU's from timer queries, CPU time on "
                  "Mesa's CPU renderers) or work (each band's rays' work, "
                  "1 + march samples per pixel: exact and free of timing noise, but not proportional to time)");
}

// The options of the outputs, the remote control and the messages.
void describeOutputAndControlOptions(cli::CommandLine& cli, RenderOptions& o)
{
    cli.add()
        ("single-screen", po::bool_switch(&o.singleScreen),
         "render the wall's whole canvas (bezels included) as one screen on one rank: the reference a wall must match")
        ("stats", po::value(&o.statsFile), "write per-frame timings to FILE (.csv or .json)")
        ("cost-map", po::value(&o.costMapFile),
         "rank 0 writes the last frame's cost per pixel to FILE (.png): each rank's render time shared among "
         "its pixels in proportion to each ray's time on the GPU's clock (GL_ARB_shader_clock), or without "
         "one to its texture fetches, in ns per pixel, as viridis on a log scale with a labelled scale bar "
         "below the wall. Draws with the static split (--balance off)")
        ("data-dir", po::value(&o.dataDir), "folder holding shaders/ (default: installed share/aurorawall or the source tree)")
        ("control-port", po::value(&o.controlPort),
         "the master takes commands on this TCP port (0: a free one, printed), one per line: status, pause, play, "
         "speed, step, time, goto, look, preset, orbit, screenshot, record, movie, quit (docs/driving.md)")
        ("web-port", po::value(&o.webPort),
         "the master serves the operator's console to a browser on this TCP port (0: a free one, printed): "
         "preview, play/pause, speed, time, presets, screenshots; the same commands as --control-port")
        ("control-bind", po::value(&o.controlBind)->default_value(o.controlBind),
         "the IPv4 address --control-port and --web-port listen on; any but loopback (127.x.x.x) needs "
         "--control-token-file")
        ("control-token-file", po::value(&o.controlTokenFile),
         "a file readable by its owner only whose first line is a shared secret: every control client's first "
         "line must be 'auth SECRET', or it gets one error line and is closed; every web request but the page's "
         "files needs the header 'Authorization: Bearer SECRET' (401 otherwise). Required for a --control-bind "
         "other than loopback")
        ("rank-timeout", po::value(&o.rankTimeoutS)->default_value(o.rankTimeoutS),
         "seconds without a heartbeat from a rank (sent by a thread of its own, so a slow frame is not "
         "silence), or without progress of its main thread outside waits for other ranks (and longer than 4 "
         "frames), after which the master names it and ends the job with exit status 3 (0.1 to 1e6)")
        ("movie", po::value(&o.movieDir),
         "the master writes every frame's wall into this folder: frame-000000.png, ... and frames.csv "
         "(frame number, animation time); every rank sends its screens every frame")
        ("movie-exr", po::bool_switch(&o.movieExr), "with --movie, also frame-000000.exr, ... (linear, half float)")
        ("record-path", po::value(&o.recordPath),
         "the master writes the camera of every frame to FILE (.toml), as it goes (at most once a second) and "
         "at the end: a scene deriving from --scene whose [[camera.key]] path, one key per frame, replays "
         "that camera at every recorded animation time")
        ("console", po::bool_switch(&o.console),
         "the master opens a console window (480 px wide, the wall's aspect) showing the whole wall, "
         "downsampled, each frame, with the HUD (H); input there steers like any window. Needs --backend glfw; "
         "every rank then sends its screens to the master every frame")
        ("print-ranks", po::bool_switch(&o.printRanks),
         "print the number of MPI ranks the wall file needs (1 with the single-screen option) and exit without "
         "rendering; runs on one process, without mpirun (launch scripts check their task count with it)")
        ("quiet", po::bool_switch(&o.quiet), "print only the summary, not a line per frame")
        ("verbose", po::bool_switch(&o.verbose), "also print the per-frame work of the components (curtain map build)");
}

// The values' ranges and the options' combinations (a usage error naming the option otherwise), and
// what one option implies for another (--cost-map: the static split).
void checkRenderOptions(const cli::CommandLine& cli, RenderOptions& o)
{
    auto check = [&cli](bool ok, const std::string& message) {
        if (!ok)
            throw cli.usageError(message);
    };
    if (cli.given("dt"))
        check(std::isfinite(o.timeStepS) && o.timeStepS >= 0 && o.timeStepS <= 1e9,
              "--dt must be a finite number of seconds in [0, 1e9]");
    check(std::isfinite(o.startTimeS) && std::abs(o.startTimeS) <= 1e15, "--start-time must be finite, |t| <= 1e15 s");
    if (cli.given("exposure"))
        check(std::isfinite(o.exposure) && o.exposure > 0 && o.exposure < 1e12, "--exposure must be a positive finite number");
    check(o.frames >= 0 && o.frames <= 100000000, "--frames must be a whole number in [0, 1e8] (got " +
                                                       std::to_string(o.frames) + ")");
    if (cli.given("control-port"))
        check(o.controlPort >= 0 && o.controlPort <= 65535, "--control-port must be in [0, 65535]");
    if (cli.given("web-port"))
        check(o.webPort >= 0 && o.webPort <= 65535, "--web-port must be in [0, 65535]");
    if (cli.given("control-port") || cli.given("web-port")) {
        try { // an address at all, before whether it needs a token
            control::bindAddressOf(o.controlBind);
        } catch (const common::UsageError& e) {
            check(false, e.what());
        }
        check(o.controlBind.rfind("127.", 0) == 0 || cli.given("control-token-file"),
              "--control-bind " + o.controlBind + " opens the control " +
                  (cli.given("control-port") ? "port" : "console") +
                  " beyond this machine: it needs --control-token-file");
    } else {
        check(!cli.given("control-bind"), "--control-bind needs --control-port or --web-port");
        check(!cli.given("control-token-file"), "--control-token-file needs --control-port or --web-port");
    }
    check(o.frames > 0 || o.backend == gl::Backend::Glfw || o.controlPort >= 0 || o.webPort >= 0,
          "--frames 0 (until a window is closed or a quit command) needs --backend glfw, --control-port or "
          "--web-port");
    if (cli.given("stats")) {
        const bool csv = o.statsFile.size() > 4 && o.statsFile.compare(o.statsFile.size() - 4, 4, ".csv") == 0;
        const bool json = o.statsFile.size() > 5 && o.statsFile.compare(o.statsFile.size() - 5, 5, ".json") == 0;
        check(csv || json, "--stats " + o.statsFile + ": the file name must end in .csv or .json");
    }
    check(std::isfinite(o.rankTimeoutS) && o.rankTimeoutS >= 0.1 && o.rankTimeoutS <= 1e6,
          "--rank-timeout must be a number of seconds in [0.1, 1e6]");
    if (cli.given("movie"))
        check(!o.movieDir.empty(), "--movie must not be empty");
    check(!o.movieExr || cli.given("movie"), "--movie-exr needs --movie");
    if (cli.given("record-path")) {
        const bool toml = o.recordPath.size() > 5 && o.recordPath.compare(o.recordPath.size() - 5, 5, ".toml") == 0;
        check(toml, "--record-path " + o.recordPath + ": the file name must end in .toml");
    }
    if (cli.given("cost-map")) {
        const bool png = o.costMapFile.size() > 4 && o.costMapFile.compare(o.costMapFile.size() - 4, 4, ".png") == 0;
        check(png, "--cost-map " + o.costMapFile + ": the file name must end in .png");
        // A band drawn by another rank brings its radiance home but not its work.
        check(o.balance != Balance::On, "--cost-map needs the static split: --balance off (or no --balance)");
        o.balance = Balance::Off;
    }
    check(!o.console || o.backend == gl::Backend::Glfw,
          "--console needs --backend glfw (the console is a window next to the wall's windows)");
    check(!o.wallFile.empty(), "--wall must not be empty");
    check(!o.sceneFile.empty(), "--scene must not be empty");
    check(!o.outDir.empty(), "--out must not be empty");
    check(o.balanceBands >= 1 && o.balanceBands <= 256, "--balance-bands must be in [1, 256]");
}

} // namespace

RenderOptions parseRenderOptions(int argc, char** argv)
{
    RenderOptions o;
    cli::CommandLine cli(
        "render",
        "Usage: mpirun -n RANKS aurorawall render --wall FILE --scene FILE [options]\n"
        "Renders the scene on the wall: rank r draws the screens the wall file gives it; rank 0\n"
        "owns the camera and the clock and broadcasts them every frame.\n"
        "Exit status, the same on every rank: 0 success, 1 runtime failure (files included), 2 usage error,\n"
        "3 a rank fell silent (--rank-timeout), 130 or 143 stopped by SIGINT or SIGTERM.\n");
    describeRenderingOptions(cli, o);
    describeOutputAndControlOptions(cli, o);
    o.helpText = cli.help();
    if (!cli.parse(argc, argv)) {
        o.help = true;
        return o;
    }
    o.timeStepS = cli.given("dt") ? o.timeStepS : -1.0;
    o.startTimeGiven = cli.given("start-time");
    checkRenderOptions(cli, o);
    return o;
}

} // namespace aurorawall::app
