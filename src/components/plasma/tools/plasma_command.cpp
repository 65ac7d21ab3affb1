#include "components/plasma/tools/plasma_command.h"

#include "cli/command_line.h"
#include "cli/exit_status.h"
#include "components/plasma/tools/plasma_accuracy.h"
#include "components/plasma/tools/plasma_soak.h"
#include "common/data_dir.h"
#include "components/plasma/gpu/gpu_verify_cases.h"
#include "components/plasma/simulation/verify_cases.h"
#include "gl/context.h"
#include "io/atomic_file.h"

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <ostream>
#include <stdexcept>
#include <string>
#include <vector>

namespace aurorawall::components::plasma::tools {

namespace pic = aurorawall::components::plasma::simulation;

namespace {

namespace po = boost::program_options;

enum class Action { Verify, Soak, Accuracy };
const cli::Choices<Action> kActions = {{"verify", Action::Verify}, {"soak", Action::Soak}, {"accuracy", Action::Accuracy}};

enum class Case { All, Langmuir, Langmuir2D, Langmuir3D, Boris, ExB, TwoStream, Energy, Heating, Landau, Diocotron };
const cli::Choices<Case> kCases = {{"all", Case::All},
                                   {"langmuir", Case::Langmuir},
                                   {"langmuir-2d", Case::Langmuir2D},
                                   {"langmuir-3d", Case::Langmuir3D},
                                   {"boris", Case::Boris},
                                   {"exb", Case::ExB},
                                   {"two-stream", Case::TwoStream},
                                   {"energy", Case::Energy},
                                   {"heating", Case::Heating},
                                   {"landau", Case::Landau},
                                   {"diocotron", Case::Diocotron}};

// The diocotron case's ω_cΔt (ω_pΔt = 0.1 ω_cΔt there).
constexpr double kDiocotronWcDt = 5.0;

enum class Device { Cpu, Gpu };
const cli::Choices<Device> kDevices = {{"cpu", Device::Cpu}, {"gpu", Device::Gpu}};

const cli::Choices<gpu::GpuPicSolver> kSolvers = {{"fft-cpu", gpu::GpuPicSolver::FftCpu},
                                                      {"jacobi", gpu::GpuPicSolver::Jacobi},
                                                      {"sor", gpu::GpuPicSolver::RedBlackSor},
                                                      {"multigrid", gpu::GpuPicSolver::Multigrid}};

const cli::Choices<pic::ParticleShape> kShapes = {{"cic", pic::ParticleShape::CloudInCell},
                                                      {"tsc", pic::ParticleShape::TriangularShapedCloud}};

// The heating case's grid spacings in Debye lengths when --dx-lambda-d is not given.
const std::vector<double> kHeatingSpacings = {0.5, 2.0, 8.0};

std::string number(double value)
{
    char text[32];
    std::snprintf(text, sizeof text, "%.7g", value);
    return text;
}

// A case's rows; a value that came out NaN or infinite ends the run (exit status 1) instead of being
// printed as if measured.
void printRows(std::ostream& out, const std::string& name, const std::vector<pic::VerifyRow>& rows)
{
    for (const pic::VerifyRow& row : rows)
        if (!std::isfinite(row.measured) || (row.expected && !std::isfinite(row.relativeError())))
            throw std::runtime_error(name + ": " + row.parameter + " came out " +
                                     number(std::isfinite(row.measured) ? row.relativeError() : row.measured) +
                                     " (the case's measurement failed at these settings)");
    for (const pic::VerifyRow& row : rows) {
        out << name << ',' << row.parameter << ',' << number(row.measured) << ',';
        if (row.expected)
            out << number(*row.expected) << ',' << number(row.relativeError());
        else
            out << ',';
        out << '\n';
    }
    out.flush();
}

// The folder of --history must exist and be writable before any case runs.
void requireWritableDirectory(const std::string& directory)
{
    if (!std::filesystem::is_directory(directory))
        throw std::runtime_error("--history: '" + directory + "' is not a directory");
    if (::access(directory.c_str(), W_OK | X_OK) != 0)
        throw std::runtime_error("--history: cannot write in '" + directory + "'");
}

// A case's history as DIRECTORY/NAME.csv, written atomically (io/atomic_file.h): no file is left
// half-written.
void writeHistory(const std::string& directory, const std::string& name, const pic::VerifyHistory& history)
{
    const std::string path = (std::filesystem::path(directory) / (name + ".csv")).string();
    try {
        io::writeFileAtomically(path, [&history](const std::string& temporary) {
            std::ofstream file(temporary);
            pic::writeHistoryCsv(file, history);
            file.close();
            if (!file)
                throw std::runtime_error("cannot write");
        });
    } catch (const std::exception& error) {
        throw std::runtime_error("--history: cannot write '" + path + "': " + error.what());
    }
}

const char* const kUsage =
    "Usage: aurorawall plasma verify [--case NAME] [--device cpu|gpu] [--solver NAME] [--wp-dt X]\n"
    "                               [--wc-dt X] [--dx-lambda-d X] [--k-lambda-d K] [--shape cic|tsc]\n"
    "                               [--history DIR]\n"
    "       aurorawall plasma soak --help, aurorawall plasma accuracy --help: the long runs of a scene's\n"
    "       plasma, the error against run time\n"
    "Runs the electrostatic particle-in-cell plasma's verification cases and prints CSV\n"
    "case,parameter,measured,expected,rel_error; expected comes from theory (frequencies and rates in\n"
    "units of the plasma frequency omega_p); rows of a run's settings, and the heating rates (no closed\n"
    "form), leave expected and rel_error empty (docs/PLASMA.md). --device gpu runs every case in GLSL\n"
    "compute shaders (float, headless EGL) instead of in double on the CPU, with the same settings,\n"
    "analysis and theory; --solver chooses their Poisson solve.\n"
    "Exit status: 0 success, 1 a run failed or output not written, 2 usage error.\n";

// The options of `plasma verify`; the initial values are the defaults --help shows.
struct VerifyOptions {
    std::string actionName;
    Case chosen = Case::All;
    Device device = Device::Cpu;
    gpu::GpuPicSolver solver = gpu::GpuPicSolver::FftCpu;
    double kDebye = 0.5;      // k λ_D of the landau case
    double wpDt = 0.2;        // ω_p Δt
    double wcDt = 1.0;        // ω_c Δt of boris and exb
    double dxOverDebye = 0.0; // --dx-lambda-d, used only when given
    pic::ParticleShape shape = pic::ParticleShape::CloudInCell;
    std::string historyDirectory;
    std::vector<double> heatingSpacings = kHeatingSpacings; // Δx/λ_D of the heating runs
};

// Declares the options in the order --help lists them.
void declareOptions(cli::CommandLine& cli, VerifyOptions& o)
{
    cli.addChoice("case", &o.chosen, kCases, "the case to run (all: each in turn)");
    cli.addChoice("device", &o.device, kDevices, "cpu: the simulation in double; gpu: in compute shaders (float)");
    cli.addChoice("solver", &o.solver, kSolvers,
                  "the Poisson solve of --device gpu: fft-cpu (exact, FFT in double on the CPU, default), "
                  "jacobi (20 Jacobi sweeps on the GPU, does not converge), sor (red-black SOR on the GPU "
                  "to 1e-6) or multigrid (6 V-cycles on the GPU)");
    cli.add()("k-lambda-d", po::value<double>(&o.kDebye)->default_value(0.5, "0.5"),
              ("the landau case's wave number times the Debye length, in [" + number(pic::kLandauMinKDebye) +
               ", " + number(pic::kLandauMaxKDebye) + "]").c_str());
    cli.add()("wp-dt", po::value<double>(&o.wpDt)->default_value(0.2, "0.2"),
              "omega_p dt of langmuir, langmuir-2d, langmuir-3d, two-stream, energy, heating and landau, in [0.01, 2): "
              "the leapfrog is unstable from 2 on, and the runs' steps grow as 1/(omega_p dt)")(
              "wc-dt", po::value<double>(&o.wcDt)->default_value(1.0),
              "omega_c dt of boris and exb, in [1e-6, 1e6] (the Boris push is stable for any; beyond, rounding "
              "hides the E x B circle, in float on the GPU from about 1e4)");
    cli.add()("dx-lambda-d", po::value<double>(&o.dxOverDebye),
              "the heating case's grid spacing in Debye lengths, in [0.01, 100] (default: 0.5, 2 and 8 in turn)");
    cli.addChoice("shape", &o.shape, kShapes,
                  "the heating case's particle shape: cic (cloud-in-cell, default) or tsc (triangular-shaped cloud)");
    cli.add()("history", po::value<std::string>(&o.historyDirectory),
              "an existing folder: each case run, except boris and exb, also writes there CASE.csv "
              "(heating: heating-dxX.csv, X = dx/lambda_D), the samples its measurement used against time "
              "(in 1/omega_p; diocotron in 1/omega_D), with the fit's window and lines");
    cli.addPositional("action", &o.actionName);
}

// Throws a usage error for the first option out of range or not applicable, in this order; a given
// --dx-lambda-d becomes the only heating spacing.
void checkOptions(const cli::CommandLine& cli, VerifyOptions& o)
{
    Action action = Action::Verify;
    if (o.actionName.empty())
        throw cli.usageError("missing the action (allowed: " + cli::wordsOf(kActions) + ")");
    if (!cli::findChoice(kActions, o.actionName, action))
        throw cli.usageError("unknown action '" + common::echoedInput(o.actionName) + "' (allowed: " + cli::wordsOf(kActions) + ")");
    if (!(o.kDebye >= pic::kLandauMinKDebye && o.kDebye <= pic::kLandauMaxKDebye))
        throw cli.usageError("--k-lambda-d must be in [" + number(pic::kLandauMinKDebye) + ", " +
                             number(pic::kLandauMaxKDebye) + "] (got " + number(o.kDebye) + ")");
    if (cli.given("k-lambda-d") && o.chosen != Case::Landau)
        throw cli.usageError("--k-lambda-d applies only to --case landau");
    if (!(o.wpDt >= pic::kMinVerifyWpDt && o.wpDt < 2.0))
        throw cli.usageError("--wp-dt must be in [" + number(pic::kMinVerifyWpDt) +
                             ", 2): the leapfrog is unstable for omega_p dt >= 2, and the runs' steps grow as "
                             "1/(omega_p dt) (got " + number(o.wpDt) + ")");
    if (!(o.wcDt >= pic::kMinVerifyWcDt && o.wcDt <= pic::kMaxVerifyWcDt))
        throw cli.usageError("--wc-dt must be in [" + number(pic::kMinVerifyWcDt) + ", " +
                             number(pic::kMaxVerifyWcDt) + "] (got " + number(o.wcDt) + ")");
    if (cli.given("dx-lambda-d")) {
        if (o.chosen != Case::Heating && o.chosen != Case::All)
            throw cli.usageError("--dx-lambda-d applies only to --case heating (or all)");
        if (!(o.dxOverDebye >= pic::kMinHeatingDxDebye && o.dxOverDebye <= pic::kMaxHeatingDxDebye))
            throw cli.usageError("--dx-lambda-d must be in [" + number(pic::kMinHeatingDxDebye) + ", " +
                                 number(pic::kMaxHeatingDxDebye) + "] (got " + number(o.dxOverDebye) + ")");
        o.heatingSpacings = {o.dxOverDebye};
    }
    if (o.device != Device::Gpu && cli.given("solver"))
        throw cli.usageError("--solver applies only to --device gpu");
    if (cli.given("shape") && o.chosen != Case::Heating)
        throw cli.usageError("--shape applies only to --case heating");
    if (o.shape != pic::ParticleShape::CloudInCell && o.device == Device::Gpu)
        throw cli.usageError("--shape tsc runs only on --device cpu (the GPU step deposits by cloud-in-cell)");
}

// Prints a case's rows, and with --history writes its history as DIRECTORY/FILE.csv.
template <typename Verify>
void runCase(const VerifyOptions& o, std::ostream& out, const std::string& name, const std::string& file,
             const Verify& verify)
{
    pic::VerifyHistory history;
    printRows(out, name, verify(o.historyDirectory.empty() ? nullptr : &history));
    if (!o.historyDirectory.empty() && !history.columns.empty())
        writeHistory(o.historyDirectory, file, history);
}

// The header, then the chosen cases (all: each in turn) on one device.
void runCases(const VerifyOptions& o, const pic::PicDevice& on, std::ostream& out)
{
    const auto runs = [&o](Case c) { return o.chosen == Case::All || o.chosen == c; };
    out << "case,parameter,measured,expected,rel_error\n";
    if (runs(Case::Langmuir))
        runCase(o, out, "langmuir", "langmuir", [&](auto h) { return pic::verifyLangmuir(o.wpDt, on, h); });
    if (runs(Case::Langmuir2D))
        runCase(o, out, "langmuir-2d", "langmuir-2d",
                [&](auto h) { return pic::verifyLangmuir2D(o.wpDt, 256, on, h); });
    if (runs(Case::Langmuir3D))
        runCase(o, out, "langmuir-3d", "langmuir-3d",
                [&](auto h) { return pic::verifyLangmuir3D(o.wpDt, 32, on, h); });
    if (runs(Case::Boris)) printRows(out, "boris", pic::verifyBoris(o.wcDt, 1000, on));
    if (runs(Case::ExB)) printRows(out, "exb", pic::verifyExB(o.wcDt, on));
    if (runs(Case::TwoStream))
        runCase(o, out, "two-stream", "two-stream", [&](auto h) { return pic::verifyTwoStream(o.wpDt, on, h); });
    if (runs(Case::Energy))
        runCase(o, out, "energy", "energy", [&](auto h) { return pic::verifyEnergy(o.wpDt, on, h); });
    if (runs(Case::Heating))
        for (const double spacing : o.heatingSpacings)
            runCase(o, out, "heating", "heating-dx" + number(spacing),
                    [&](auto h) { return pic::verifyHeating(o.wpDt, spacing, 1, on, 64, h); });
    if (runs(Case::Landau))
        runCase(o, out, "landau", "landau",
                [&](auto h) { return pic::verifyLandau(o.wpDt, o.kDebye, 1 << 20, on, h); });
    if (runs(Case::Diocotron))
        runCase(o, out, "diocotron", "diocotron",
                [&](auto h) { return pic::verifyDiocotron(kDiocotronWcDt, 0.1, on, h); });
}

} // namespace

int runPlasmaCommand(int argc, char** argv, std::ostream& out, std::ostream& err)
{
    if (argc > 1 && std::string(argv[1]) == "soak") return runPlasmaSoakCommand(argc - 1, argv + 1, out, err);
    if (argc > 1 && std::string(argv[1]) == "accuracy") return runPlasmaAccuracyCommand(argc - 1, argv + 1, out, err);
    return cli::runCommand("plasma", out, err, [&] {
        cli::CommandLine cli("plasma", kUsage);
        VerifyOptions options;
        declareOptions(cli, options);
        if (!cli.parse(argc, argv)) {
            out << cli.help();
            return;
        }
        checkOptions(cli, options);
        if (cli.given("history")) requireWritableDirectory(options.historyDirectory);
        if (options.device == Device::Gpu) {
            const auto context = gl::createContext(gl::Backend::Egl);
            runCases(options, gpu::GpuPicDevice(common::dataDirectory() + "/shaders", options.solver), out);
        } else {
            runCases(options, pic::cpuDevice(options.shape), out);
        }
    });
}

} // namespace aurorawall::components::plasma::tools
