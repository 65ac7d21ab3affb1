#include "app/render_options.h"

#include "common/input_error.h"

#include <boost/program_options.hpp>

#include <cmath>
#include <sstream>

namespace aurorawall::app {

namespace po = boost::program_options;

RenderOptions parseRenderOptions(int argc, char** argv)
{
    RenderOptions o;
    po::options_description desc(
        "Usage: mpirun -n RANKS aurorawall render --wall FILE --scene FILE [options]\n"
        "Renders the scene on the wall: rank r draws the screens the wall file gives it; rank 0\n"
        "owns the camera and the clock and broadcasts them every frame.\n\nOptions");
    desc.add_options()
        ("help,h", "show this help")
        ("wall", po::value(&o.wallFile)->required(), "wall file (config/walls/*.toml): screens, bezels, eye, ranks")
        ("scene", po::value(&o.sceneFile)->required(), "scene file (config/scenes/*.toml): components and parameters")
        ("backend", po::value(&o.backend)->default_value(o.backend),
         "OpenGL backend: egl (headless; GPU or Mesa llvmpipe), osmesa (headless), glfw (one window per screen)")
        ("frames", po::value(&o.frames)->default_value(o.frames),
         "number of frames to render; 0 = until a window is closed (glfw)")
        ("dt", po::value(&o.timeStepS), "animation time step per frame in seconds (default: the scene's time_step_s)")
        ("start-time", po::value(&o.startTimeS), "animation time of the first frame in seconds (default: the scene's)")
        ("realtime", po::bool_switch(&o.realTime), "animation time follows the master's wall clock instead of --dt")
        ("exposure", po::value(&o.exposure), "multiplies radiance for the PNG preview and windows (default: the scene's)")
        ("tonemap", po::value(&o.toneMap)->default_value(o.toneMap),
         "preview curve: aces (ACES filmic + sRGB) or magnitude-gamma (Lawlor & Genetti)")
        ("out", po::value(&o.outDir)->default_value(o.outDir), "output folder for images")
        ("gather", po::bool_switch(&o.gather), "rank 0 assembles the whole wall: OUT/wall.exr and OUT/wall.png")
        ("tiles", po::bool_switch(&o.tiles), "every rank writes its tiles: OUT/tile-<screen>.exr (linear, half float)")
        ("balance", po::value(&o.balance)->default_value(o.balance)->implicit_value("on"),
         "dynamic load balancing, on|off|auto (auto: on with more than one rank): every screen is cut into "
         "bands, and each frame ranks with cheap screens render bands of expensive ones (split from measured "
         "costs, damped); the image is unchanged. Costs a readback and a transfer of the moved bands per frame")
        ("balance-bands", po::value(&o.balanceBands)->default_value(o.balanceBands),
         "bands per screen for --balance (1 to 256; at most one per 8 rows)")
        ("balance-by", po::value(&o.balanceBy)->default_value(o.balanceBy),
         "what --balance equalizes: time (each band's measured CPU time) or work (each band's rays' work, "
         "1 + aurora samples per pixel: exact and free of timing noise, but not proportional to time)")
        ("draw-lanes", po::value(&o.drawLanes)->default_value(o.drawLanes),
         "benchmarks with more ranks than cores: at most N ranks draw at once, taking turns (0: all at once), "
         "each on a core of its own (N = the number of cores); the image is unchanged")
        ("single-screen", po::bool_switch(&o.singleScreen),
         "render the wall's whole canvas (bezels included) as one screen on one rank: the reference a wall must match")
        ("stats", po::value(&o.statsFile), "write per-frame timings to FILE (.csv or .json)")
        ("data-dir", po::value(&o.dataDir), "folder holding shaders/ (default: installed share/aurorawall or the source tree)")
        ("quiet", po::bool_switch(&o.quiet), "print only the summary, not a line per frame")
        ("verbose", po::bool_switch(&o.verbose), "also print the per-frame work of the components (curtain map build)");
    std::ostringstream help;
    help << desc;
    o.helpText = help.str();

    po::variables_map vm;
    try {
        po::store(po::command_line_parser(argc, argv).options(desc).run(), vm);
        if (vm.count("help")) {
            o.help = true;
            return o;
        }
        po::notify(vm);
    } catch (const po::error& e) {
        throw InputError(std::string("render: ") + e.what() + " (see aurorawall render --help)");
    }
    o.timeStepS = vm.count("dt") ? o.timeStepS : -1.0;
    o.startTimeGiven = vm.count("start-time") != 0;
    auto check = [](bool ok, const std::string& message) {
        if (!ok)
            throw InputError(message);
    };
    if (vm.count("dt"))
        check(std::isfinite(o.timeStepS) && o.timeStepS >= 0 && o.timeStepS <= 1e9,
              "--dt must be a finite number of seconds in [0, 1e9]");
    check(std::isfinite(o.startTimeS) && std::abs(o.startTimeS) <= 1e15, "--start-time must be finite, |t| <= 1e15 s");
    if (vm.count("exposure"))
        check(std::isfinite(o.exposure) && o.exposure > 0 && o.exposure < 1e12, "--exposure must be a positive finite number");
    check(o.toneMap == "aces" || o.toneMap == "magnitude-gamma", "--tonemap must be aces or magnitude-gamma (got '" + o.toneMap + "')");
    check(o.frames >= 0 && o.frames <= 100000000, "--frames must be a whole number in [0, 1e8] (got " +
                                                       std::to_string(o.frames) + ")");
    if (vm.count("stats")) {
        const bool csv = o.statsFile.size() > 4 && o.statsFile.compare(o.statsFile.size() - 4, 4, ".csv") == 0;
        const bool json = o.statsFile.size() > 5 && o.statsFile.compare(o.statsFile.size() - 5, 5, ".json") == 0;
        check(csv || json, "--stats " + o.statsFile + ": the file name must end in .csv or .json");
    }
    check(!o.outDir.empty(), "--out must not be empty");
    check(o.balanceBands >= 1 && o.balanceBands <= 256, "--balance-bands must be in [1, 256]");
    check(o.drawLanes >= 0 && o.drawLanes <= 4096, "--draw-lanes must be in [0, 4096]");
    check(o.balanceBy == "work" || o.balanceBy == "time", "--balance-by must be work or time (got '" + o.balanceBy + "')");
    check(o.balance == "on" || o.balance == "off" || o.balance == "auto",
          "--balance must be on, off or auto (got '" + o.balance + "')");
    return o;
}

} // namespace aurorawall::app
