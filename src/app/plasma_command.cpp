#include "app/plasma_command.h"

#include "app/cli/command_line.h"
#include "app/cli/exit_status.h"
#include "app/plasma_accuracy.h"
#include "app/plasma_soak.h"
#include "common/data_dir.h"
#include "components/plasma/gpu/gpu_verify_cases.h"
#include "components/plasma/simulation/verify_cases.h"
#include "gl/context.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <cstdio>
#include <ostream>
#include <string>
#include <vector>

namespace aurorawall::app {
namespace {

namespace po = boost::program_options;

enum class Action { Verify, Soak, Accuracy };
const cli::Choices<Action> kActions = {{"verify", Action::Verify}, {"soak", Action::Soak}, {"accuracy", Action::Accuracy}};

enum class Case { All, Langmuir, Langmuir2D, Boris, ExB, TwoStream, Energy, Heating, Landau, Diocotron };
const cli::Choices<Case> kCases = {{"all", Case::All},
                                   {"langmuir", Case::Langmuir},
                                   {"langmuir-2d", Case::Langmuir2D},
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

const cli::Choices<plasma::GpuPicSolver> kSolvers = {{"fft-cpu", plasma::GpuPicSolver::FftCpu},
                                                      {"jacobi", plasma::GpuPicSolver::Jacobi},
                                                      {"sor", plasma::GpuPicSolver::RedBlackSor},
                                                      {"multigrid", plasma::GpuPicSolver::Multigrid}};

// The heating case's grid spacings in Debye lengths when --dx-lambda-d is not given.
const std::vector<double> kHeatingSpacings = {0.5, 2.0, 8.0};

std::string number(double value)
{
    char text[32];
    std::snprintf(text, sizeof text, "%.7g", value);
    return text;
}

void printRows(std::ostream& out, const std::string& name, const std::vector<plasma::VerifyRow>& rows)
{
    for (const plasma::VerifyRow& row : rows) {
        out << name << ',' << row.parameter << ',' << number(row.measured) << ',';
        if (row.expected)
            out << number(*row.expected) << ',' << number(row.relativeError());
        else
            out << ',';
        out << '\n';
    }
    out.flush();
}

} // namespace

int runPlasmaCommand(int argc, char** argv, std::ostream& out, std::ostream& err)
{
    if (argc > 1 && std::string(argv[1]) == "soak") return runPlasmaSoakCommand(argc - 1, argv + 1, out, err);
    if (argc > 1 && std::string(argv[1]) == "accuracy") return runPlasmaAccuracyCommand(argc - 1, argv + 1, out, err);
    return cli::runCommand("plasma", out, err, [&] {
        cli::CommandLine cli(
            "plasma",
            "Usage: aurorawall plasma verify [--case NAME] [--device cpu|gpu] [--solver NAME] [--wp-dt X]\n"
            "                               [--wc-dt X] [--dx-lambda-d X]\n"
            "       aurorawall plasma soak --help, aurorawall plasma accuracy --help: the long runs of a scene's\n"
            "       plasma, the error against run time\n"
            "Runs the electrostatic particle-in-cell plasma's verification cases and prints CSV\n"
            "case,parameter,measured,expected,rel_error; expected comes from theory (frequencies and rates in\n"
            "units of the plasma frequency omega_p); rows of a run's settings, and the heating rates (no closed\n"
            "form), leave expected and rel_error empty (docs/PLASMA.md). --device gpu runs langmuir, langmuir-2d,\n"
            "boris and exb in GLSL compute shaders (float, headless EGL) instead of in double on the CPU;\n"
            "--solver chooses their Poisson solve.\n"
            "Exit status: 0 success, 1 a run failed or output not written, 2 usage error.\n");
        std::string actionName;
        Case chosen = Case::All;
        double wpDt = 0.2, wcDt = 1.0;
        std::vector<double> heatingSpacings = kHeatingSpacings;
        Device device = Device::Cpu;
        cli.addChoice("case", &chosen, kCases, "the case to run (all: each in turn)");
        cli.addChoice("device", &device, kDevices,
                      "cpu: the simulation in double; gpu: in compute shaders (langmuir, langmuir-2d, boris, exb)");
        plasma::GpuPicSolver solver = plasma::GpuPicSolver::FftCpu;
        cli.addChoice("solver", &solver, kSolvers,
                      "the Poisson solve of --device gpu: fft-cpu (exact, FFT in double on the CPU, default), "
                      "jacobi (20 Jacobi sweeps on the GPU, does not converge), sor (red-black SOR on the GPU "
                      "to 1e-6) or multigrid (6 V-cycles on the GPU)");
        cli.add()("wp-dt", po::value<double>(&wpDt)->default_value(0.2, "0.2"),
                  "omega_p dt of langmuir, langmuir-2d, two-stream, energy, heating and landau, in (0, 2): the leapfrog is unstable "
                  "from 2 on")("wc-dt", po::value<double>(&wcDt)->default_value(1.0),
                              "omega_c dt of boris and exb, > 0 (the Boris push is stable for any)");
        double dxOverDebye = 0.0;
        cli.add()("dx-lambda-d", po::value<double>(&dxOverDebye),
                  "the heating case's grid spacing in Debye lengths, > 0 (default: 0.5, 2 and 8 in turn)");
        cli.addPositional("action", &actionName);
        if (!cli.parse(argc, argv)) {
            out << cli.help();
            return;
        }
        Action action = Action::Verify;
        if (actionName.empty())
            throw cli.usageError("missing the action (allowed: " + cli::wordsOf(kActions) + ")");
        if (!cli::findChoice(kActions, actionName, action))
            throw cli.usageError("unknown action '" + actionName + "' (allowed: " + cli::wordsOf(kActions) + ")");
        if (!(wpDt > 0.0 && wpDt < 2.0))
            throw cli.usageError("--wp-dt must be in (0, 2): the leapfrog is unstable for omega_p dt >= 2 (got " +
                                 number(wpDt) + ")");
        if (!(wcDt > 0.0) || !std::isfinite(wcDt))
            throw cli.usageError("--wc-dt must be a finite number > 0 (got " + number(wcDt) + ")");
        if (cli.given("dx-lambda-d")) {
            if (!(dxOverDebye > 0.0) || !std::isfinite(dxOverDebye))
                throw cli.usageError("--dx-lambda-d must be a finite number > 0 (got " + number(dxOverDebye) + ")");
            heatingSpacings = {dxOverDebye};
        }

        const bool onGpu = device == Device::Gpu;
        const Case gpuCases[] = {Case::All, Case::Langmuir, Case::Langmuir2D, Case::Boris, Case::ExB};
        if (onGpu && std::find(std::begin(gpuCases), std::end(gpuCases), chosen) == std::end(gpuCases))
            throw cli.usageError("--device gpu runs only the cases langmuir, langmuir-2d, boris and exb");
        if (!onGpu && cli.given("solver"))
            throw cli.usageError("--solver applies only to --device gpu");

        out << "case,parameter,measured,expected,rel_error\n";
        if (onGpu) {
            const auto context = gl::createContext(gl::Backend::Egl);
            const std::string shaderDir = dataDirectory() + "/shaders";
            const auto runs = [chosen](Case c) { return chosen == Case::All || chosen == c; };
            if (runs(Case::Langmuir))
                printRows(out, "langmuir", plasma::verifyLangmuirOnGpu(wpDt, shaderDir, solver));
            if (runs(Case::Langmuir2D))
                printRows(out, "langmuir-2d", plasma::verifyLangmuir2DOnGpu(wpDt, shaderDir, 256, solver));
            if (runs(Case::Boris)) printRows(out, "boris", plasma::verifyBorisOnGpu(wcDt, shaderDir));
            if (runs(Case::ExB)) printRows(out, "exb", plasma::verifyExBOnGpu(wcDt, shaderDir));
            return;
        }
        const auto runs = [chosen](Case c) { return chosen == Case::All || chosen == c; };
        if (runs(Case::Langmuir)) printRows(out, "langmuir", plasma::verifyLangmuir(wpDt));
        if (runs(Case::Langmuir2D)) printRows(out, "langmuir-2d", plasma::verifyLangmuir2D(wpDt));
        if (runs(Case::Boris)) printRows(out, "boris", plasma::verifyBoris(wcDt));
        if (runs(Case::ExB)) printRows(out, "exb", plasma::verifyExB(wcDt));
        if (runs(Case::TwoStream)) printRows(out, "two-stream", plasma::verifyTwoStream(wpDt));
        if (runs(Case::Energy)) printRows(out, "energy", plasma::verifyEnergy(wpDt));
        if (runs(Case::Heating))
            for (const double spacing : heatingSpacings)
                printRows(out, "heating", plasma::verifyHeating(wpDt, spacing));
        if (runs(Case::Landau)) printRows(out, "landau", plasma::verifyLandau(wpDt));
        if (runs(Case::Diocotron)) printRows(out, "diocotron", plasma::verifyDiocotron(kDiocotronWcDt));
    });
}

} // namespace aurorawall::app
