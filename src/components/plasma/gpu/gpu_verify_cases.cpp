#include "components/plasma/gpu/gpu_verify_cases.h"

#include "common/constants.h"
#include "components/plasma/gpu/gpu_pic.h"
#include "components/plasma/simulation/dispersion.h"
#include "components/plasma/simulation/particle_loading.h"
#include "components/plasma/simulation/plasma_parameters.h"

#include <glm/geometric.hpp>

#include <cmath>
#include <complex>
#include <stdexcept>

namespace aurorawall::plasma {
namespace {

// The settings of verify_cases.cpp: the cases' results depend only on the dimensionless numbers.
constexpr double kDensity = 1e12;      // m⁻³
constexpr double kMagneticField = 5e-5; // T

VerifyRow setting(const std::string& name, double value)
{
    return {name, value, std::nullopt};
}

void requireLeapfrogStable(double wpDt)
{
    if (!(wpDt > 0.0 && wpDt < 2.0))
        throw std::domain_error("omega_p dt must be in (0, 2): the leapfrog is unstable from 2 on");
}

void requirePositive(double wcDt)
{
    if (!(wcDt > 0.0) || !std::isfinite(wcDt))
        throw std::domain_error("omega_c dt must be a finite number > 0");
}

// The mode's field over 20 plasma periods, s_n = Im Σ_nodes (E·axis) e^{−i k·x} (up to a constant
// factor), and the frequency it oscillates at in units of ω_p.
double modeFrequency(GpuPic& pic, double wpDt)
{
    const PeriodicGrid& grid = pic.grid();
    const int n = grid.cells[0];
    std::vector<double> s;
    const long steps = long(std::ceil(20 * 2.0 * kPi / wpDt));
    for (long step = 0; step <= steps; ++step) {
        const std::vector<glm::dvec3> e = pic.nodeField();
        std::complex<double> sum = 0.0;
        for (int j = 0; j < grid.cells[1]; ++j)
            for (int i = 0; i < n; ++i) {
                const glm::dvec3& node = e[grid.index(i, j, 0)];
                const double along = grid.dimension == 1 ? node.x : node.x + node.y;
                sum += along * std::polar(1.0, -2.0 * kPi * double((i + j) % n) / n);
            }
        s.push_back(sum.imag());
        pic.step();
    }
    return sampledCosineFrequency(s) / wpDt;
}

// One test particle's velocities over `steps` steps (the first at −Δt/2) in B along z and E.
std::vector<glm::dvec3> testParticleVelocities(double wcDt, glm::dvec3 start, glm::dvec3 electricField, long steps,
                                               const std::string& shaderDir)
{
    const double dt = wcDt / cyclotronFrequency(kMagneticField);
    const PeriodicGrid grid(1, {8, 1, 1}, {1.0, 1.0, 1.0});
    Particles electron;
    electron.position = {glm::dvec3(4.0, 0.5, 0.5)};
    electron.velocity = {start};
    electron.weight = 0.0;
    GpuPic pic(grid, electron, glm::dvec3(0.0, 0.0, kMagneticField), dt, shaderDir, electricField);
    std::vector<glm::dvec3> v;
    for (long n = 0; n <= steps; ++n) {
        v.push_back(pic.velocities()[0]);
        pic.step();
    }
    return v;
}

} // namespace

std::vector<VerifyRow> verifyLangmuirOnGpu(double wpDt, const std::string& shaderDir, GpuPicSolver solver)
{
    requireLeapfrogStable(wpDt);
    constexpr int kCells = 1024, kParticles = 8 * kCells;
    const double dt = wpDt / plasmaFrequency(kDensity), length = 1.0;
    const PeriodicGrid grid(1, {kCells, 1, 1}, {length / kCells, 1.0, 1.0});
    GpuPic pic(grid, quietStart(grid, kParticles, kDensity, {1, 0.01 * length / kCells}, glm::dvec3(0.0)),
               glm::dvec3(0.0), dt, shaderDir, glm::dvec3(0.0), solver);
    const double omega = modeFrequency(pic, wpDt);
    return {setting("wp_dt", wpDt), setting("cells", kCells), setting("particles", kParticles),
            setting("quantum_bits", pic.quantumBits()), {"omega_over_wp", omega, leapfrogPlasmaFrequency(wpDt)}};
}

std::vector<VerifyRow> verifyLangmuir2DOnGpu(double wpDt, const std::string& shaderDir, int cells,
                                             GpuPicSolver solver)
{
    requireLeapfrogStable(wpDt);
    const double dt = wpDt / plasmaFrequency(kDensity), spacing = 1.0 / cells;
    const PeriodicGrid grid(2, {cells, cells, 1}, {spacing, spacing, 1.0});
    GpuPic pic(grid, diagonalWaveLattice(grid, 1, kDensity, {1, 0.01 * spacing}), glm::dvec3(0.0), dt, shaderDir,
               glm::dvec3(0.0), solver);
    const double omega = modeFrequency(pic, wpDt);
    return {setting("wp_dt", wpDt), setting("cells_per_axis", cells), setting("particles", double(cells) * cells),
            setting("quantum_bits", pic.quantumBits()), {"omega_over_wp", omega, leapfrogPlasmaFrequency(wpDt)}};
}

std::vector<VerifyRow> verifyBorisOnGpu(double wcDt, const std::string& shaderDir, long steps)
{
    requirePositive(wcDt);
    const std::vector<glm::dvec3> v = testParticleVelocities(wcDt, {3e5, 0.0, 1e5}, glm::dvec3(0.0), steps, shaderDir);
    const double speed = glm::length(v[0]);
    double angle = 0.0, speedChange = 0.0;
    for (std::size_t n = 1; n < v.size(); ++n) {
        const glm::dvec3 a = v[n - 1], b = v[n];
        angle += std::abs(std::atan2(a.x * b.y - a.y * b.x, a.x * b.x + a.y * b.y));
        speedChange = std::max(speedChange, std::abs(glm::length(v[n]) - speed) / speed);
    }
    return {setting("wc_dt", wcDt), setting("steps", double(steps)),
            {"rotation_per_step_rad", angle / double(steps), borisRotationPerStep(wcDt)},
            {"max_relative_speed_change", speedChange, 0.0}};
}

std::vector<VerifyRow> verifyExBOnGpu(double wcDt, const std::string& shaderDir)
{
    requirePositive(wcDt);
    constexpr long kSteps = 1000;
    const glm::dvec3 b(0.0, 0.0, kMagneticField), e(0.5, 0.0, 0.0); // T, V/m: E/B = 1e4 m/s
    const glm::dvec3 drift = glm::cross(e, b) / glm::dot(b, b);
    const double scale = glm::length(e) / glm::length(b);
    const std::vector<glm::dvec3> v = testParticleVelocities(wcDt, glm::dvec3(0.0), e, kSteps + 1, shaderDir);
    // The centre of the Boris velocity circle: the circumcentre of three successive velocities.
    glm::dvec3 centre(0.0);
    for (std::size_t n = 0; n + 2 < v.size(); ++n) {
        const glm::dvec3 a = v[n + 1] - v[n], c = v[n + 2] - v[n];
        const double d = 2.0 * (a.x * c.y - a.y * c.x);
        const double aa = glm::dot(a, a), cc = glm::dot(c, c);
        centre += v[n] + glm::dvec3((c.y * aa - a.y * cc) / d, (a.x * cc - c.x * aa) / d, 0.0);
    }
    centre /= double(kSteps);
    const glm::dvec3 alongDrift = drift / glm::length(drift), alongE = e / glm::length(e);
    return {setting("wc_dt", wcDt), setting("steps", double(kSteps)),
            {"drift_along_ExB_over_E_over_B", glm::dot(centre, alongDrift) / scale, glm::length(drift) / scale},
            {"drift_along_E_over_E_over_B", glm::dot(centre, alongE) / scale, glm::dot(drift, alongE) / scale}};
}

} // namespace aurorawall::plasma
