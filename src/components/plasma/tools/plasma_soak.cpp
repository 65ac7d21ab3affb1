#include "components/plasma/tools/plasma_soak.h"

#include "cli/command_line.h"
#include "cli/exit_status.h"
#include "common/data_dir.h"
#include "components/plasma/gpu/gpu_verify_cases.h"
#include "components/plasma/simulation/electron_sheet.h"
#include "components/plasma/simulation/verify_cases.h"
#include "components/plasma/simulation/plasma_parameters.h"
#include "components/registry.h"
#include "gl/context.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <ostream>
#include <stdexcept>

namespace aurorawall::components::plasma::tools {

namespace pic = aurorawall::components::plasma::simulation;

namespace {

namespace po = boost::program_options;
using components::plasma::BoxFramesSpec;

enum class Device { Cpu, Gpu };
const cli::Choices<Device> kDevices = {{"cpu", Device::Cpu}, {"gpu", Device::Gpu}};

std::string number(double value)
{
    char text[32];
    std::snprintf(text, sizeof text, "%.9g", value);
    return text;
}

[[noreturn]] void failCheck(const std::string& name, long step, const std::string& what)
{
    throw std::runtime_error(name + ": step " + std::to_string(step) + ": " + what);
}

void checkVectors(const std::string& name, long step, const std::vector<glm::dvec3>& values, const char* quantity,
                  const char* item)
{
    for (std::size_t i = 0; i < values.size(); ++i)
        for (int a = 0; a < 3; ++a)
            if (!std::isfinite(values[i][a]))
                failCheck(name, step, std::string(quantity) + " " + "xyz"[a] + " of " + item + " " + std::to_string(i) +
                                          " is " + number(values[i][a]));
}

// Every position finite and inside the box [0, L] (the wrap x − L⌊x/L⌋ can round to L itself).
void checkPositions(const std::string& name, long step, const std::vector<glm::dvec3>& positions, glm::dvec3 box)
{
    checkVectors(name, step, positions, "position", "electron");
    for (std::size_t i = 0; i < positions.size(); ++i)
        for (int a = 0; a < 3; ++a)
            if (positions[i][a] < 0.0 || positions[i][a] > box[a])
                failCheck(name, step, std::string("position ") + "xyz"[a] + " of electron " + std::to_string(i) + " = " +
                                          number(positions[i][a]) + " m is outside the box [0, " + number(box[a]) + "]");
}

void soak(const SoakSimulation& s, pic::PicRun& sim, long steps, long every, std::ostream& out)
{
    const glm::dvec3 box = s.grid.boxLength();
    // n₀, the box's mean electron density (m⁻³): the ion background's.
    const double meanDensity = s.electrons.weight * double(s.electrons.position.size()) / (box.x * box.y * box.z);
    for (long n = 0;; ++n) {
        const bool row = n % every == 0 || n == steps;
        double maxField = 0.0, maxDensity = 0.0;
        if (row) {
            const std::vector<glm::dvec3> field = sim.nodeField();
            checkSoakState(s.name, n, sim.positions(), sim.velocities(), field, box);
            for (const glm::dvec3& e : field)
                maxField = std::max(maxField, glm::length(e));
            // ρ = −e(n − n₀): n/n₀ = 1 − ρ/(e n₀).
            for (double rho : sim.chargeDensity())
                maxDensity = std::max(maxDensity, 1.0 - rho / (pic::kElementaryCharge * meanDensity));
        }
        const pic::StepEnergies e = sim.stepWithEnergies();
        if (row) {
            if (!std::isfinite(e.total()))
                failCheck(s.name, n, "the energy is " + number(e.total()));
            out << s.name << ',' << n << ',' << number(n * s.dt) << ',' << number(e.field) << ',' << number(e.kinetic)
                << ',' << number(e.total()) << ',' << number(maxField) << ',' << number(maxDensity) << '\n';
            out.flush();
        }
        if (n == steps)
            return;
    }
}

} // namespace

void checkSoakState(const std::string& name, long step, const std::vector<glm::dvec3>& positions,
                    const std::vector<glm::dvec3>& velocities, const std::vector<glm::dvec3>& nodeField, glm::dvec3 box)
{
    checkPositions(name, step, positions, box);
    checkVectors(name, step, velocities, "velocity", "electron");
    checkVectors(name, step, nodeField, "electric field", "node");
}

std::vector<SoakSimulation> soakSimulations(const components::plasma::Settings& plasma)
{
    const pic::ElectronSheetSpec sheet = components::plasma::sheetFramesSpec(plasma).sheet;
    std::vector<SoakSimulation> runs;
    runs.push_back({"strip", pic::sheetGrid(sheet), pic::sheetElectrons(sheet),
                    glm::dvec3(0.0, 0.0, sheet.magneticFieldT), pic::sheetTimeStep(sheet)});
    if (plasma.kind == components::plasma::Settings::Kind::Box) {
        const BoxFramesSpec box = components::plasma::boxFramesSpec(plasma);
        runs.push_back({"box", components::plasma::boxGrid(box), components::plasma::boxElectrons(box),
                        glm::dvec3(0.0, 0.0, box.magneticFieldT), box.timeStepS});
    }
    return runs;
}

int runPlasmaSoakCommand(int argc, char** argv, std::ostream& out, std::ostream& err)
{
    return cli::runCommand("plasma soak", out, err, [&] {
        cli::CommandLine cli(
            "plasma soak",
            "Usage: aurorawall plasma soak --scene FILE [--steps N] [--every M] [--device cpu|gpu]\n"
            "Steps each of the scene's plasma simulations (the strip; with kind = \"box\" also the box) N times\n"
            "from the component's start and prints CSV simulation,step,time_s,field_energy_j,kinetic_energy_j,\n"
            "total_energy_j,max_abs_e_v_per_m,max_density_over_n0 at step 0, every M steps and at step N (n0: the\n"
            "box's mean electron density). At each row every electron's position must be finite and inside the\n"
            "box, and every velocity and node field value finite; the first that is not ends the run with one\n"
            "line naming the simulation, step and quantity (docs/PLASMA.md).\n"
            "Exit status: 0 success, 1 a check failed or the scene could not be read, 2 usage error.\n");
        std::string sceneFile;
        long steps = 100000, every = 1000;
        Device device = Device::Cpu;
        cli.add()("scene", po::value<std::string>(&sceneFile)->required(), "the scene file (TOML) listing plasma")(
            "steps", po::value<long>(&steps)->default_value(steps), "time steps per simulation, >= 1")(
            "every", po::value<long>(&every)->default_value(every), "steps between rows and checks, >= 1");
        cli.addChoice("device", &device, kDevices,
                      "cpu: ElectrostaticPic in double; gpu: GpuPic in compute shaders (float, headless EGL)");
        if (!cli.parse(argc, argv)) {
            out << cli.help();
            return;
        }
        if (steps < 1)
            throw cli.usageError("--steps must be >= 1 (got " + std::to_string(steps) + ")");
        if (every < 1)
            throw cli.usageError("--every must be >= 1 (got " + std::to_string(every) + ")");
        const scene::Scene scene = components::loadScene(sceneFile);
        if (!scene.has("plasma"))
            throw std::runtime_error(sceneFile + ": the scene does not list plasma");
        const std::vector<SoakSimulation> runs = soakSimulations(scene.settings<components::plasma::Settings>());

        out << "simulation,step,time_s,field_energy_j,kinetic_energy_j,total_energy_j,max_abs_e_v_per_m,"
               "max_density_over_n0\n";
        const auto runAll = [&](const pic::PicDevice& on) {
            for (const SoakSimulation& s : runs)
                soak(s, *on.run(s.grid, s.electrons, s.magneticField, s.dt), steps, every, out);
        };
        if (device == Device::Gpu) {
            const auto context = gl::createContext(gl::Backend::Egl);
            runAll(gpu::GpuPicDevice(common::dataDirectory() + "/shaders"));
        } else {
            runAll(pic::cpuDevice());
        }
    });
}

} // namespace aurorawall::components::plasma::tools
