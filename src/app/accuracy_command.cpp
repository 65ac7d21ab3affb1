#include "app/accuracy_command.h"

#include "physics/atmosphere/accuracy_report.h"
#include "cli/command_line.h"
#include "cli/exit_status.h"
#include "components/tools.h"

#include <algorithm>
#include <cstdio>
#include <ostream>
#include <string>
#include <vector>

namespace aurorawall::app {
namespace {

namespace po = boost::program_options;

// The options of each kind of run; giving one to the other kind is a usage error.
const std::vector<std::string> kShaderOptions = {"repeat", "copies", "view-steps", "light-steps"};
const std::vector<std::string> kSceneOptions = {"wall", "size", "pixels", "frame", "runs", "threads",
                                                "reference-step-km", "feature-costs", "work-stats", "views", "seed"};
// The --scene options that the components' tables (components/tools.h) do not take.
const std::vector<std::string> kSceneOnlyOptions = {"pixels", "threads", "reference-step-km", "feature-costs",
                                                    "work-stats", "views", "seed"};

// After "Usage: aurorawall accuracy --airmass | --sky [options]\n" (the tables of physics::atmosphere).
const char* kUsageHead =
    "       aurorawall accuracy --scene FILE [--wall FILE] [--size WxH] [--pixels N] [--frame K] [--feature-costs]\n"
    "       aurorawall accuracy --scene FILE --work-stats [--wall FILE] [--size WxH] [--frame K]\n"
    "       aurorawall accuracy --scene FILE --views N [--seed S] [--wall FILE] [--size WxH] [--pixels N] [--frame K]\n";
const char* kUsageBody =
    "Error against cost of the approximations (docs/ACCURACY.md), on one headless EGL context in one\n"
    "process (no mpirun).\n"
    "--airmass: every airmass method over the sweep's rays; --sky: the single-scattering sky with 1, 2, 4 and\n"
    "8 lights, closed form against nested march. Errors are against the double-precision reference, for the\n"
    "float results read back from the GPU and for the CPU float32/float64 evaluations of the same shader\n"
    "text. Costs are ns per evaluation inside a compute shader on this machine's GL renderer, an empty loop\n"
    "subtracted.\n";
// After "--scene: error against run time of the quality knobs (" and those of the component whose march it is.
const char* kSceneUsage =
    "):\nthe scene's frame K (default 0, the first) at a small size, each knob varied alone around the scene's\n"
    "defaults, compared with the GPU render at the\n"
    "finest settings (every pixel) and the double-precision CPU reference (N sampled pixels). The components\n"
    "the CPU reference does not model are removed. --feature-costs: instead, the frame time of each\n"
    "feature toggled alone, the full scene (the paper's table 2). --work-stats: instead, the work of the\n"
    "march per pixel, counted on the GPU: march steps, curtains evaluated, sub-steps and texture fetches, as\n"
    "the mean per pixel and the mean over 8x4-pixel blocks of each block's largest (what a 32-lane warp\n"
    "waits for), for the full scene with its defaults (CSV). --views N: instead, the defaults' error against\n"
    "both references at N views drawn at random from seed S (cameras on the ground, inside the auroral\n"
    "layer, above it and far in space, in turn, near frame K's camera, at random times; CSV).\n";

// The options of the atmosphere physics' tables (physics::atmosphere::shaderTables), "--airmass" and
// "--sky", joined by `separator`.
std::string shaderTableOptions(const std::string& separator)
{
    std::string text;
    for (const physics::atmosphere::ShaderTable& t : physics::atmosphere::shaderTables())
        text += (text.empty() ? "--" : separator + "--") + t.option;
    return text;
}

// Whether one of the atmosphere physics' tables is given.
bool shaderTableGiven(const cli::CommandLine& cli)
{
    const auto& tables = physics::atmosphere::shaderTables();
    return std::any_of(tables.begin(), tables.end(), [&](const auto& t) { return cli.given(t.option); });
}

// The usage text: the generic runs, then each component's table.
std::string usage()
{
    std::string text = "Usage: aurorawall accuracy " + shaderTableOptions(" | ") + " [options]\n" + kUsageHead;
    for (const components::AccuracyTable& t : components::componentAccuracyTables())
        text += "       aurorawall accuracy --" + std::string(t.option) + " FILE [--wall FILE] [--size WxH] [--runs N]\n";
    text += kUsageBody;
    text += std::string("--scene: error against run time of the quality knobs (") + components::componentSceneSweepKnobs() +
            kSceneUsage;
    for (const components::AccuracyTable& t : components::componentAccuracyTables())
        text += "--" + std::string(t.option) + ": " + t.description;
    return text + "Exit status: 0 success, 1 runtime failure (a file, no GL context, a shader), 2 usage error.\n";
}

// The generic runs (the atmosphere physics' tables, "--scene FILE"), then "--OPTION FILE" for each
// component's table.
std::string runChoices()
{
    std::vector<std::string> runs;
    for (const physics::atmosphere::ShaderTable& t : physics::atmosphere::shaderTables())
        runs.push_back("--" + std::string(t.option));
    runs.push_back("--scene FILE");
    for (const components::AccuracyTable& t : components::componentAccuracyTables())
        runs.push_back("--" + std::string(t.option) + " FILE");
    std::string text = runs.front();
    for (size_t i = 1; i < runs.size(); ++i)
        text += (i + 1 == runs.size() ? " or " : ", ") + runs[i];
    return text;
}

// The component's table whose option is given, or none.
const components::AccuracyTable* givenTable(const cli::CommandLine& cli)
{
    for (const components::AccuracyTable& t : components::componentAccuracyTables())
        if (cli.given(t.option))
            return &t;
    return nullptr;
}

// The CPU reference's step where a curtain is in reach, km: at most the GPU reference's 0.25 km (a
// coarser one is no reference), at least 0.001 km (50 times the default's steps; its run time grows as
// 1/step, and at 1e-300 it would never end).
constexpr double kMinReferenceStepKm = 0.001;
constexpr double kMaxReferenceStepKm = 0.25;
// The most views of one --views run (each a few seconds on llvmpipe).
constexpr int kMaxViews = 10000;
// Bounds that keep a mistyped count from running for hours or exhausting memory: the CPU reference's
// threads, the rendered pixels (a 4096x4096 view), and the shader tables' work counts.
constexpr int kMaxThreads = 1024;
constexpr long long kMaxSizePixels = 4096LL * 4096LL;
constexpr int kMaxShaderCount = 65536; // --repeat, --copies
constexpr int kMaxSkySteps = 4096;     // --view-steps, --light-steps

// "WxH" with positive W and H.
bool parseSize(const std::string& text, glm::ivec2& size)
{
    int w = 0, h = 0;
    char x = 0, rest = 0;
    if (std::sscanf(text.c_str(), "%d%c%d%c", &w, &x, &h, &rest) != 3 || x != 'x' || w < 1 || h < 1)
        return false;
    size = {w, h};
    return true;
}

// The options of every kind of run; the initial values are the defaults --help shows.
struct AccuracyOptions {
    physics::atmosphere::AccuracyReportSettings shader;  // the atmosphere physics' tables
    accuracy::SceneAccuracySettings scene; // --scene, a component's table
    std::string size = "320x180"; // --size, parsed into scene.sizePx
    long long seed = 1;           // --seed, checked non-negative into scene.seed
};

void declareOptions(cli::CommandLine& cli, AccuracyOptions& o)
{
    physics::atmosphere::AccuracyReportSettings& shader = o.shader;
    accuracy::SceneAccuracySettings& scene = o.scene;
    for (const physics::atmosphere::ShaderTable& t : physics::atmosphere::shaderTables())
        cli.add()(t.option, po::bool_switch(), t.help);
    cli.add()
        ("scene", po::value(&scene.sceneFile), "the march's quality knobs on this scene file");
    for (const components::AccuracyTable& t : components::componentAccuracyTables())
        cli.add()(t.option, po::value(&scene.sceneFile), t.help);
    cli.add()
        ("repeat", po::value(&shader.airmassRepeat)->default_value(shader.airmassRepeat),
         "--airmass: airmass evaluations per shader invocation (1 to 65536)")
        ("copies", po::value(&shader.copies),
         "--airmass, --sky: work per dispatch in copies of the ray set (default: 1 on llvmpipe, 64 on a GPU)")
        ("view-steps", po::value(&shader.viewSteps)->default_value(shader.viewSteps), "--sky: outer march steps M (1 to 4096)")
        ("light-steps", po::value(&shader.lightSteps)->default_value(shader.lightSteps),
         "--sky: nested-march steps K per light (1 to 4096)")
        ("wall", po::value(&scene.wallFile),
         "--scene: wall file whose single-screen equivalent sets the field of view (default "
         "config/walls/single.toml)")
        ("size", po::value(&o.size)->default_value(o.size), "--scene: render size WxH in pixels (at most 4096x4096 in all, and what the GL device can draw)")
        ("pixels", po::value(&scene.pixels)->default_value(scene.pixels), "--scene: pixels of the CPU reference")
        ("frame", po::value(&scene.frame)->default_value(scene.frame),
         "--scene: the scene's frame K as render draws it (its start time plus K time steps, the camera "
         "moved along its path)")
        ("runs", po::value(&scene.runs)->default_value(scene.runs),
         "--scene: timed frames per setting after one warm-up (the median is reported)")
        ("threads", po::value(&scene.threads)->default_value(scene.threads), "--scene: CPU reference threads (1 to 1024)")
        ("reference-step-km", po::value(&scene.referenceStepKm)->default_value(scene.referenceStepKm),
         "--scene: CPU reference step where a curtain is in reach, 0.001 to 0.25 km")
        ("feature-costs", po::bool_switch(&scene.featureCosts),
         "--scene: the paper's table 2 (frame time of each feature) instead of the knobs")
        ("work-stats", po::bool_switch(&scene.workStats),
         "--scene: the march's work per pixel and per 8x4-pixel block instead of the knobs (CSV)")
        ("views", po::value(&scene.views),
         "--scene: the defaults' error at this many views drawn at random instead of the knobs (1 to 10000)")
        ("seed", po::value(&o.seed)->default_value(o.seed), "--views: the seed the views are drawn from (0 to 2^63 - 1)");
}

// Throws a usage error unless exactly one kind of run is chosen (the atmosphere physics' tables go
// together) and every option given applies to it.
void checkRunKind(const cli::CommandLine& cli)
{
    const components::AccuracyTable* table = givenTable(cli);
    for (const components::AccuracyTable& t : components::componentAccuracyTables())
        if (table && table != &t && cli.given(t.option))
            throw cli.usageError("--" + std::string(table->option) + " cannot be combined with --" + t.option);
    if (table && cli.given("scene"))
        throw cli.usageError("--" + std::string(table->option) + " cannot be combined with --scene");
    const std::string runName = table ? "--" + std::string(table->option) : "--scene";
    const bool sceneRun = cli.given("scene") || table;
    if (sceneRun && shaderTableGiven(cli))
        throw cli.usageError(runName + " cannot be combined with " + shaderTableOptions(" or "));
    if (!sceneRun && !shaderTableGiven(cli))
        throw cli.usageError("choose " + runChoices());
    for (const std::string& option : sceneRun ? kShaderOptions : kSceneOptions)
        if (cli.given(option))
            throw cli.usageError("--" + option + " applies to " + (sceneRun ? shaderTableOptions(" and ") : "--scene") +
                                 " only");
    if (table)
        for (const std::string& option : kSceneOnlyOptions)
            if (cli.given(option))
                throw cli.usageError("--" + option + " applies to --scene only");
}

// --scene or a component's table: the options checked, then the run.
void runSceneKnobs(const cli::CommandLine& cli, AccuracyOptions& o, std::ostream& out)
{
    const components::AccuracyTable* table = givenTable(cli);
    accuracy::SceneAccuracySettings& scene = o.scene;
    if (scene.sceneFile.empty())
        throw cli.usageError((table ? "--" + std::string(table->option) : std::string("--scene")) + " needs a file name");
    if (!parseSize(o.size, scene.sizePx))
        throw cli.usageError("--size must be WxH with positive whole W and H (got '" + common::echoedInput(o.size) + "')");
    if (static_cast<long long>(scene.sizePx.x) * scene.sizePx.y > kMaxSizePixels)
        throw cli.usageError("--size " + o.size + ": more than " + std::to_string(kMaxSizePixels) + " pixels");
    if (scene.frame < 0 || scene.frame > 100000000)
        throw cli.usageError("--frame must be a whole number in [0, 1e8] (got " + std::to_string(scene.frame) + ")");
    if (cli.given("views") && !(scene.views >= 1 && scene.views <= kMaxViews))
        throw cli.usageError("--views must be a whole number in [1, 10000] (got " + std::to_string(scene.views) + ")");
    if (cli.given("seed") && !cli.given("views"))
        throw cli.usageError("--seed applies to --views only");
    if (o.seed < 0)
        throw cli.usageError("--seed must be a whole number >= 0 (got " + std::to_string(o.seed) + ")");
    scene.seed = std::uint64_t(o.seed);
    if (int(scene.featureCosts) + int(scene.workStats) + int(cli.given("views")) > 1)
        throw cli.usageError("choose at most one of --feature-costs, --work-stats and --views");
    if (scene.pixels < 1 || scene.runs < 1 || scene.threads < 1)
        throw cli.usageError("--pixels, --runs and --threads must be positive");
    if (scene.threads > kMaxThreads)
        throw cli.usageError("--threads must be at most " + std::to_string(kMaxThreads) + " (got " +
                             std::to_string(scene.threads) + ")");
    if (!(scene.referenceStepKm >= kMinReferenceStepKm && scene.referenceStepKm <= kMaxReferenceStepKm)) {
        char got[32];
        std::snprintf(got, sizeof got, "%g", scene.referenceStepKm);
        throw cli.usageError("--reference-step-km must be in [0.001, 0.25] km (got " + std::string(got) + ")");
    }
    if (table)
        table->run(scene, out);
    else if (const components::SceneSweep sweep = components::componentSceneSweep())
        sweep(scene, out);
    else
        throw cli.usageError("--scene: no compiled-in component sweeps a scene's knobs");
}

// The atmosphere physics' tables given: the options checked, then the tables on one GL context.
void runShaderTables(const cli::CommandLine& cli, const AccuracyOptions& o, std::ostream& out)
{
    const physics::atmosphere::AccuracyReportSettings& shader = o.shader;
    if (shader.airmassRepeat < 1 || shader.viewSteps < 1 || shader.lightSteps < 1 ||
        (cli.given("copies") && shader.copies < 1))
        throw cli.usageError("--repeat, --copies, --view-steps and --light-steps must be >= 1");
    if (shader.airmassRepeat > kMaxShaderCount || shader.copies > kMaxShaderCount)
        throw cli.usageError("--repeat and --copies must be at most " + std::to_string(kMaxShaderCount));
    if (shader.viewSteps > kMaxSkySteps || shader.lightSteps > kMaxSkySteps)
        throw cli.usageError("--view-steps and --light-steps must be at most " + std::to_string(kMaxSkySteps));
    const auto context = accuracy::openAccuracyContext(out);
    for (const physics::atmosphere::ShaderTable& t : physics::atmosphere::shaderTables())
        if (cli.given(t.option))
            t.print(shader, out);
}

} // namespace

int runAccuracyCommand(int argc, char** argv, std::ostream& out, std::ostream& err)
{
    return cli::runCommand("accuracy", out, err, [&] {
        cli::CommandLine cli("accuracy", usage());
        AccuracyOptions options;
        declareOptions(cli, options);
        if (!cli.parse(argc, argv)) {
            out << cli.help();
            return;
        }
        checkRunKind(cli);
        if (cli.given("scene") || givenTable(cli))
            runSceneKnobs(cli, options, out);
        else
            runShaderTables(cli, options, out);
    });
}

} // namespace aurorawall::app
