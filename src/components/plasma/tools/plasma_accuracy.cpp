#include "physics/constants.h"
#include "components/plasma/tools/plasma_accuracy.h"

#include "cli/command_line.h"
#include "cli/exit_status.h"
#include "components/plasma/simulation/discrete_laplacian.h"
#include "components/plasma/simulation/electrostatic_pic.h"
#include "components/plasma/simulation/fft_poisson_solver.h"
#include "components/plasma/simulation/jacobi_poisson.h"
#include "components/plasma/simulation/particle_loading.h"
#include "components/plasma/simulation/particle_mesh.h"
#include "components/plasma/simulation/plasma_parameters.h"
#include "components/plasma/simulation/verify_cases.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <functional>
#include <ostream>
#include <stdexcept>

namespace aurorawall::components::plasma::tools {

namespace pic = aurorawall::components::plasma::simulation;

namespace {


constexpr double kDensity = 1e12;      // m⁻³
constexpr double kThermalSpeed = 4.19e5; // m/s: 1 eV electrons

const int kParticlesPerCell[] = {1, 2, 4, 8, 16, 32, 64};
const double kWpDt[] = {0.05, 0.1, 0.2, 0.4, 0.8, 1.2, 1.5};

enum class Table { All, Particles, TimeStep, Solvers, Heating };
const cli::Choices<Table> kTables = {{"all", Table::All},
                                     {"particles", Table::Particles},
                                     {"time-step", Table::TimeStep},
                                     {"solvers", Table::Solvers},
                                     {"heating", Table::Heating}};

double milliseconds(const std::function<void()>& work)
{
    const auto start = std::chrono::steady_clock::now();
    work();
    return 1e3 * std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

double debyeLength() { return pic::debyeLength(kThermalSpeed, kDensity); }

pic::PeriodicGrid thermalGrid(int dimension, int cellsPerAxis)
{
    const double d = debyeLength();
    return dimension == 1   ? pic::PeriodicGrid(1, {cellsPerAxis, 1, 1}, {d, 1.0, 1.0})
           : dimension == 2 ? pic::PeriodicGrid(2, {cellsPerAxis, cellsPerAxis, 1}, {d, d, 1.0})
                            : pic::PeriodicGrid(3, {cellsPerAxis, cellsPerAxis, cellsPerAxis}, {d, d, d});
}

double relativeL2(const std::vector<glm::dvec3>& value, const std::vector<glm::dvec3>& reference)
{
    double difference = 0.0, norm = 0.0;
    for (std::size_t n = 0; n < value.size(); ++n) {
        const glm::dvec3 d = value[n] - reference[n];
        difference += glm::dot(d, d);
        norm += glm::dot(reference[n], reference[n]);
    }
    return std::sqrt(difference / norm);
}

std::string number(double value)
{
    char text[32];
    std::snprintf(text, sizeof text, "%.4g", value);
    return text;
}

void printParticles(std::ostream& out)
{
    out << "dimension,start,particles_per_cell,density_noise,closed_form,rel_error,ms_per_step\n";
    const struct {
        int dimension;
        bool quiet;
    } runs[] = {{1, false}, {1, true}, {2, false}};
    for (const auto& run : runs)
        for (int ppc : kParticlesPerCell) {
            const DensityNoiseRow r = densityNoise(run.dimension, run.quiet, ppc);
            out << r.dimension << ',' << (r.quiet ? "quiet" : "random") << ',' << ppc << ',' << number(r.noise) << ','
                << number(r.closedForm) << ','
                << (r.closedForm > 0.0 ? number(std::abs(r.noise - r.closedForm) / r.closedForm) : "") << ','
                << number(r.msPerStep) << '\n';
            out.flush();
        }
}

void printTimeSteps(std::ostream& out)
{
    out << "plasma,wp_dt,steps,relative_energy_error,closed_form,ms_per_step\n";
    for (const char* plasma : {"cold", "thermal"})
        for (double wpDt : kWpDt) {
            const EnergyErrorRow r = energyError(plasma, wpDt);
            out << r.plasma << ',' << r.wpDt << ',' << r.steps << ',' << number(r.relativeEnergyError) << ','
                << (r.closedForm ? number(*r.closedForm) : "") << ',' << number(r.msPerStep) << '\n';
            out.flush();
        }
}

void printSolvers(std::ostream& out)
{
    out << "grid,solver,sweeps,poisson_residual,field_error,ms_per_solve\n";
    for (const auto& [dimension, cells] : {std::pair{2, 256}, std::pair{3, 64}})
        for (const SolverRow& r : solverTable(dimension, cells)) {
            out << r.grid << ',' << r.solver << ',' << (r.sweeps > 0 ? std::to_string(r.sweeps) : "-") << ','
                << number(r.residual) << ',' << number(r.fieldError) << ',' << number(r.msPerSolve) << '\n';
            out.flush();
        }
}

void printHeating(std::ostream& out)
{
    out << "particles_per_cell,wp_dt,seed,heating_rate_over_wp,ms_per_step\n";
    const auto print = [&out](const HeatingRow& r) {
        out << r.particlesPerCell << ',' << r.wpDt << ',' << r.seed << ',' << number(r.rate) << ','
            << number(r.msPerStep) << '\n';
        out.flush();
    };
    for (int ppc : {8, 16, 32, 64, 128})
        for (int seed : {1, 2})
            print(heatingRate(ppc, 0.2, seed));
    for (double wpDt : {0.05, 0.1, 0.4, 0.8, 1.2})
        for (int seed : {1, 2})
            print(heatingRate(64, wpDt, seed));
}

} // namespace

DensityNoiseRow densityNoise(int dimension, bool quiet, int particlesPerCell)
{
    if (quiet && dimension != 1)
        throw std::invalid_argument("densityNoise: the quiet start is 1D");
    // 4096 nodes in 1D and 2D: the RMS over them is good to about 1/√(2·4096) ≈ 1.1%.
    const pic::PeriodicGrid grid = thermalGrid(dimension, dimension == 1 ? 4096 : 64);
    const int count = particlesPerCell * int(grid.nodeCount());
    const pic::Particles electrons =
        quiet ? pic::quietMaxwellian(grid, count, kDensity, pic::Perturbation{1, 0.0}, kThermalSpeed)
              : pic::randomStart(grid, count, kDensity, kThermalSpeed, 1);
    DensityNoiseRow r;
    r.dimension = dimension;
    r.quiet = quiet;
    r.particlesPerCell = particlesPerCell;
    double sum = 0.0;
    for (double rho : pic::depositChargeDensity(grid, electrons)) {
        const double relative = -rho / (pic::kElementaryCharge * kDensity); // n/n₀ − 1, ρ = −e(n − n₀)
        sum += relative * relative;
    }
    r.noise = std::sqrt(sum / double(grid.nodeCount()));
    r.closedForm = quiet ? 0.0 : std::sqrt(std::pow(2.0 / 3.0, dimension) / particlesPerCell - 1.0 / count);
    pic::ElectrostaticPic sim(grid, electrons, glm::dvec3(0.0), 0.2 / pic::plasmaFrequency(kDensity));
    std::vector<double> ms;
    for (int n = 0; n < 5; ++n)
        ms.push_back(milliseconds([&] { sim.step(); }));
    std::nth_element(ms.begin(), ms.begin() + 2, ms.end());
    r.msPerStep = ms[2];
    return r;
}

EnergyErrorRow energyError(const std::string& plasma, double wpDt)
{
    if (!(wpDt > 0.0 && wpDt < 2.0))
        throw std::invalid_argument("energyError: omega_p dt must be in (0, 2)");
    const double dt = wpDt / pic::plasmaFrequency(kDensity);
    EnergyErrorRow r;
    r.plasma = plasma;
    r.wpDt = wpDt;
    pic::ElectrostaticPic sim = [&] {
        if (plasma == "cold") {
            const pic::PeriodicGrid grid(1, {256, 1, 1}, {1.0, 1.0, 1.0});
            r.steps = long(std::ceil(20.0 * 2.0 * physics::kPi / wpDt));
            r.closedForm = 2.0 * wpDt * wpDt / (4.0 + wpDt * wpDt);
            return pic::ElectrostaticPic(grid, pic::quietStart(grid, 8 * 256, kDensity, {1, 0.01}, glm::dvec3(0.0)),
                                         glm::dvec3(0.0), dt);
        }
        if (plasma == "thermal") {
            const pic::PeriodicGrid grid = thermalGrid(1, 64);
            r.steps = long(std::ceil(100.0 / wpDt));
            return pic::ElectrostaticPic(grid, pic::randomStart(grid, 64 * 64, kDensity, kThermalSpeed, 1),
                                         glm::dvec3(0.0), dt);
        }
        throw std::invalid_argument("energyError: unknown plasma '" + plasma + "'");
    }();
    double initial = 0.0;
    r.msPerStep = milliseconds([&] {
                      initial = sim.step().total();
                      for (long n = 1; n < r.steps; ++n)
                          r.relativeEnergyError =
                              std::max(r.relativeEnergyError, std::abs(sim.step().total() - initial) / initial);
                  }) /
                  double(r.steps);
    return r;
}

std::vector<SolverRow> solverTable(int dimension, int cellsPerAxis)
{
    const pic::PeriodicGrid grid = thermalGrid(dimension, cellsPerAxis);
    const std::string name = std::to_string(cellsPerAxis) + "^" + std::to_string(dimension);
    const std::vector<double> rho =
        pic::depositChargeDensity(grid, pic::randomStart(grid, 2 * int(grid.nodeCount()), kDensity, kThermalSpeed, 1));
    const pic::FftPoissonSolver fft(grid);
    std::vector<double> exact;
    fft.solve(rho); // untimed: the first solve touches the plans' memory
    const double fftMs = milliseconds([&] { exact = fft.solve(rho); });
    const std::vector<glm::dvec3> exactField = pic::nodeElectricField(grid, exact);
    std::vector<SolverRow> rows = {{name, "fft", 0, pic::poissonResidual(grid, rho, exact), 0.0, fftMs}};
    for (int sweeps : {20, 200}) {
        std::vector<double> phi(grid.nodeCount(), 0.0);
        const double ms = milliseconds([&] { pic::jacobiSweeps(grid, rho, phi, sweeps); });
        rows.push_back({name, "jacobi", sweeps, pic::poissonResidual(grid, rho, phi),
                        relativeL2(pic::nodeElectricField(grid, phi), exactField), ms});
    }
    return rows;
}

HeatingRow heatingRate(int particlesPerCell, double wpDt, int seed)
{
    HeatingRow r{particlesPerCell, wpDt, seed, 0.0, 0.0};
    std::vector<pic::VerifyRow> rows;
    const double ms = milliseconds([&] {
        rows = pic::verifyHeating(wpDt, 8.0, std::uint64_t(seed), pic::cpuDevice(), particlesPerCell);
    });
    r.msPerStep = ms / std::ceil(pic::kHeatingRunEndWp / wpDt);
    for (const pic::VerifyRow& row : rows)
        if (row.parameter == "heating_rate_over_wp")
            r.rate = row.measured;
    return r;
}

int runPlasmaAccuracyCommand(int argc, char** argv, std::ostream& out, std::ostream& err)
{
    return cli::runCommand("plasma accuracy", out, err, [&] {
        cli::CommandLine cli(
            "plasma accuracy",
            "Usage: aurorawall plasma accuracy [--table all|particles|time-step|solvers|heating]\n"
            "The particle-in-cell plasma's error against its run time, as CSV tables, the cost measured on the spot\n"
            "(ms of wall-clock time on this machine): particles, the density noise of a thermal plasma against\n"
            "particles per cell against its closed form for a random start; time-step, the largest relative\n"
            "energy error over a fixed physical time against omega_p dt; solvers, the Poisson residual and the\n"
            "field error against the FFT of Jacobi's 20 and 200 sweeps; heating, the numerical heating rate at\n"
            "dx = 8 Debye lengths against particles per cell and omega_p dt (docs/PLASMA.md).\n"
            "Exit status: 0 success, 1 output not written, 2 usage error.\n");
        Table table = Table::All;
        cli.addChoice("table", &table, kTables, "the table to print (all: each in turn, after a blank line)");
        if (!cli.parse(argc, argv)) {
            out << cli.help();
            return;
        }
        const auto prints = [table](Table t) { return table == Table::All || table == t; };
        bool first = true;
        const auto separate = [&] {
            if (!first) out << '\n';
            first = false;
        };
        if (prints(Table::Particles)) separate(), printParticles(out);
        if (prints(Table::TimeStep)) separate(), printTimeSteps(out);
        if (prints(Table::Solvers)) separate(), printSolvers(out);
        if (prints(Table::Heating)) separate(), printHeating(out);
    });
}

} // namespace aurorawall::components::plasma::tools
