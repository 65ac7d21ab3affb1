#include "components/plasma/simulation/verify_cases.h"

#include "physics/constants.h"
#include "common/glsl.h"
#include "components/plasma/simulation/dispersion.h"
#include "components/plasma/simulation/electron_sheet.h"
#include "components/plasma/simulation/electrostatic_pic.h"
#include "components/plasma/simulation/particle_loading.h"
#include "components/plasma/simulation/plasma_parameters.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdio>
#include <limits>
#include <memory>
#include <ostream>
#include <stdexcept>

// The push in double (this file's own copy: electrostatic_pic.cpp and particle_mesh.cpp compile theirs
// into the same namespace; not every function is used here).
namespace aurorawall::components::plasma::simulation::f64 {
namespace {
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
AURORAWALL_GLSL_PRECISION(double)
#include "components/plasma/boris_push.glsl"
#pragma GCC diagnostic pop
} // namespace
} // namespace aurorawall::components::plasma::simulation::f64

namespace aurorawall::components::plasma::simulation {
namespace {

// An ionospheric F-region electron density (m⁻³) and a geomagnetic field strength (T); the cases'
// results depend only on the dimensionless numbers.
constexpr double kDensity = 1e12;
constexpr double kMagneticField = 5e-5;
constexpr double kChargeOverMass = -kElementaryCharge / kElectronMass;

VerifyRow setting(const std::string& name, double value)
{
    return {name, value, std::nullopt};
}

// The Fourier coefficient of E_x along x for `mode` on a 1D grid: Σ_j E_j exp(−i k x_j) · 2/n.
std::complex<double> fieldMode(const std::vector<glm::dvec3>& e, int mode)
{
    const int n = int(e.size());
    std::complex<double> sum = 0.0;
    for (int j = 0; j < n; ++j)
        sum += e[j].x * std::polar(1.0, -2.0 * physics::kPi * mode * j / n);
    return sum * (2.0 / n);
}

// The field of the wave k = 2π(1, …, 1)/L along the diagonal d of a square or cubic grid of n cells
// per axis: Im Σ_nodes (E·d) exp(−i k·x) up to a constant factor (in 1D Im Ê_x of mode 1), sin-like
// for a displacement ∝ sin(k·x); the phase depends on (i + j + k) mod n only.
double diagonalMode(const std::vector<glm::dvec3>& e, const PeriodicGrid& grid)
{
    const int n = grid.cells[0];
    std::vector<std::complex<double>> phase(n);
    for (int m = 0; m < n; ++m)
        phase[m] = std::polar(1.0, -2.0 * physics::kPi * m / n);
    std::complex<double> sum = 0.0;
    for (int k = 0; k < grid.cells[2]; ++k)
        for (int j = 0; j < grid.cells[1]; ++j)
            for (int i = 0; i < n; ++i) {
                const glm::dvec3& node = e[grid.index(i, j, k)];
                double along = node.x;
                if (grid.dimension >= 2) along += node.y;
                if (grid.dimension == 3) along += node.z;
                sum += along * phase[(i + j + k) % n];
            }
    return sum.imag();
}

// The frequency ω/ω_p of the diagonal wave over 20 plasma periods; the history holds the mode s_n
// against ω_p t, and the measured and expected frequencies (the leapfrog's cold wave is exactly
// s_0 cos(ωnΔt), from rest).
double diagonalWaveFrequency(PicRun& run, const PeriodicGrid& grid, double wpDt, VerifyHistory* history)
{
    std::vector<double> s;
    const long steps = long(std::ceil(20 * 2.0 * physics::kPi / wpDt));
    for (long n = 0; n <= steps; ++n) {
        s.push_back(diagonalMode(run.nodeField(), grid));
        run.step();
    }
    const double omega = sampledCosineFrequency(s) / wpDt;
    if (history) {
        history->columns = {"t_wp", "field_mode"};
        for (long n = 0; n <= steps; ++n)
            history->rows.push_back({double(n) * wpDt, s[n]});
        history->fit = {{"fit_start", 0.0},
                        {"fit_end", double(steps) * wpDt},
                        {"amplitude", s[0]},
                        {"fitted_omega", omega},
                        {"expected_omega", leapfrogPlasmaFrequency(wpDt)}};
    }
    return omega;
}

// The case's settings, then the device's, then the measurements.
std::vector<VerifyRow> rows(std::vector<VerifyRow> settings, const std::vector<VerifyRow>& deviceSettings,
                            const std::vector<VerifyRow>& measured)
{
    settings.insert(settings.end(), deviceSettings.begin(), deviceSettings.end());
    settings.insert(settings.end(), measured.begin(), measured.end());
    return settings;
}

void requireResolvedGyration(double wcDt)
{
    if (!(wcDt >= kMinVerifyWcDt && wcDt <= kMaxVerifyWcDt))
        throw std::domain_error("omega_c dt must be in [1e-6, 1e6]");
}

class CpuRun : public PicRun {
public:
    CpuRun(const PeriodicGrid& grid, const Particles& electrons, glm::dvec3 magneticField, double dt,
           ParticleShape shape)
        : pic_(grid, electrons, magneticField, dt, shape)
    {
    }
    void step() override { pic_.step(); }
    StepEnergies stepWithEnergies() override { return pic_.step(); }
    const std::vector<glm::dvec3>& nodeField() override { return pic_.nodeField(); }
    std::vector<glm::dvec3> positions() override { return pic_.electrons().position; }
    std::vector<glm::dvec3> velocities() override { return pic_.electrons().velocity; }
    std::vector<double> chargeDensity() override
    {
        return depositChargeDensity(pic_.grid(), pic_.electrons(), pic_.shape());
    }

private:
    ElectrostaticPic pic_;
};

class CpuDevice : public PicDevice {
public:
    explicit CpuDevice(ParticleShape shape) : shape_(shape) {}
    std::unique_ptr<PicRun> run(const PeriodicGrid& grid, const Particles& electrons, glm::dvec3 magneticField,
                                double dt) const override
    {
        return std::make_unique<CpuRun>(grid, electrons, magneticField, dt, shape_);
    }
    std::vector<glm::dvec3> testParticleVelocities(glm::dvec3 start, glm::dvec3 electricField, glm::dvec3 magneticField,
                                                   double dt, long steps) const override
    {
        std::vector<glm::dvec3> v = {start};
        for (long n = 0; n < steps; ++n)
            v.push_back(f64::borisVelocity(v.back(), electricField, magneticField, kChargeOverMass, dt));
        return v;
    }
    std::vector<VerifyRow> settings(std::size_t, int) const override
    {
        if (shape_ == ParticleShape::TriangularShapedCloud)
            return {{"particle_shape_nodes_per_axis", 3.0, std::nullopt}};
        return {};
    }

private:
    ParticleShape shape_;
};

// A straight line y = intercept + slope·t.
struct Line {
    double slope = 0.0, intercept = 0.0;
    double at(double t) const { return intercept + slope * t; }
};

// The least-squares line through the samples (t, y) with t ≥ from.
Line fittedLine(const std::vector<double>& t, const std::vector<double>& y,
                double from = -std::numeric_limits<double>::infinity())
{
    double mt = 0.0, my = 0.0, count = 0.0;
    for (std::size_t i = 0; i < t.size(); ++i)
        if (t[i] >= from) {
            mt += t[i];
            my += y[i];
            count += 1.0;
        }
    mt /= count;
    my /= count;
    double stt = 0.0, sty = 0.0;
    for (std::size_t i = 0; i < t.size(); ++i)
        if (t[i] >= from) {
            stt += (t[i] - mt) * (t[i] - mt);
            sty += (t[i] - mt) * (y[i] - my);
        }
    const double slope = sty / stt;
    return {slope, my - slope * mt};
}

constexpr double kNoValue = std::numeric_limits<double>::quiet_NaN();

// The history of an exponential phase fitted from fitStart on: the amplitude exp(logAmplitude) at
// every sample, whether the fit used it, the fitted line exp(a + γt) and the theory's exp(a' + γ₀t),
// which meets the fitted one at the middle of the window.
VerifyHistory exponentialHistory(const std::string& timeName, const std::string& amplitudeName,
                                 const std::vector<double>& t, const std::vector<double>& logAmplitude,
                                 double fitStart, Line fit, double expectedRate)
{
    const double middle = 0.5 * (fitStart + t.back());
    const Line theory{expectedRate, fit.at(middle) - expectedRate * middle};
    VerifyHistory history;
    history.columns = {timeName, amplitudeName, "in_fit", "fitted", "expected"};
    for (std::size_t i = 0; i < t.size(); ++i)
        history.rows.push_back({t[i], std::exp(logAmplitude[i]), t[i] >= fitStart ? 1.0 : 0.0,
                                std::exp(fit.at(t[i])), std::exp(theory.at(t[i]))});
    history.fit = {{"fit_start", fitStart},        {"fit_end", t.back()},
                   {"fitted_rate", fit.slope},     {"fitted_intercept", fit.intercept},
                   {"expected_rate", expectedRate}, {"expected_intercept", theory.intercept}};
    return history;
}

// An exponential phase: its samples (time, log amplitude) and the line fitted from fitStart on.
struct ExponentialPhase {
    std::vector<double> t, logAmplitude;
    Line fit;
};

// Steps `run` through steps 0 … last, sampling logAmplitude() at the steps from time fitStart on,
// or at every step when allSamples (for a history); a step is omegaDt in the time's unit.
template <class LogAmplitude>
ExponentialPhase sampledExponentialPhase(PicRun& run, double omegaDt, double fitStart, long last, bool allSamples,
                                         LogAmplitude logAmplitude)
{
    ExponentialPhase phase;
    for (long n = 0; n <= last; ++n) {
        const double time = n * omegaDt;
        if (allSamples || time >= fitStart) {
            phase.t.push_back(time);
            phase.logAmplitude.push_back(logAmplitude());
        }
        run.step();
    }
    phase.fit = fittedLine(phase.t, phase.logAmplitude, fitStart);
    return phase;
}

void requireLeapfrogStable(double wpDt)
{
    if (!(wpDt >= kMinVerifyWpDt && wpDt < 2.0))
        throw std::domain_error("omega_p dt must be in [0.01, 2): the leapfrog is unstable from 2 on");
}

} // namespace

// The frequency ωΔt of a leapfrog mode: a sampled cosine s_n obeys s_{n+1} + s_{n−1} = 2 cos(ωΔt) s_n
// exactly, so cos(ωΔt) by least squares over the samples.
double sampledCosineFrequency(const std::vector<double>& s)
{
    double numerator = 0.0, denominator = 0.0;
    for (std::size_t n = 1; n + 1 < s.size(); ++n) {
        numerator += s[n] * (s[n + 1] + s[n - 1]);
        denominator += 2.0 * s[n] * s[n];
    }
    return std::acos(numerator / denominator);
}

void writeHistoryCsv(std::ostream& out, const VerifyHistory& history)
{
    const auto number = [](double value) {
        if (std::isnan(value)) return std::string();
        char text[32];
        std::snprintf(text, sizeof text, "%.9g", value);
        return std::string(text);
    };
    for (const auto& [name, value] : history.fit)
        out << "# " << name << " = " << number(value) << '\n';
    for (std::size_t c = 0; c < history.columns.size(); ++c)
        out << (c ? "," : "") << history.columns[c];
    out << '\n';
    for (const std::vector<double>& row : history.rows) {
        for (std::size_t c = 0; c < row.size(); ++c)
            out << (c ? "," : "") << number(row[c]);
        out << '\n';
    }
}

double VerifyRow::relativeError() const
{
    const double e = expected.value_or(0.0);
    return e != 0.0 ? std::abs(measured - e) / std::abs(e) : std::abs(measured - e);
}

const PicDevice& cpuDevice(ParticleShape shape)
{
    static const CpuDevice cloudInCell(ParticleShape::CloudInCell);
    static const CpuDevice triangularShapedCloud(ParticleShape::TriangularShapedCloud);
    return shape == ParticleShape::CloudInCell ? cloudInCell : triangularShapedCloud;
}

std::vector<VerifyRow> verifyLangmuir(double wpDt, const PicDevice& device, VerifyHistory* history)
{
    requireLeapfrogStable(wpDt);
    // Mode 1 on 1024 cells: kΔx = 0.006, so the grid's own dispersion (a relative −(kΔx)²/8 in ω) stays
    // below 1e-5; 8 cold particles per cell, displaced by a hundredth of a cell.
    constexpr int kCells = 1024, kParticles = 8 * kCells;
    const double wp = plasmaFrequency(kDensity), dt = wpDt / wp;
    const double length = 1.0; // m; a cold plasma has no length scale of its own
    const PeriodicGrid grid(1, {kCells, 1, 1}, {length / kCells, 1.0, 1.0});
    const std::unique_ptr<PicRun> run = device.run(
        grid, quietStart(grid, kParticles, kDensity, {1, 0.01 * length / kCells}, glm::dvec3(0.0)), glm::dvec3(0.0), dt);
    const double omega = diagonalWaveFrequency(*run, grid, wpDt, history);
    return rows({setting("wp_dt", wpDt), setting("cells", kCells), setting("particles", kParticles)},
                device.settings(kParticles, 1), {{"omega_over_wp", omega, leapfrogPlasmaFrequency(wpDt)}});
}

namespace {

// Mode (1, …, 1) on cells^dimension cells, one cold particle per cell displaced along the diagonal by
// a hundredth of a cell: ω/ω_p against the leapfrog's relation. The grid's dispersion, a relative
// −(|k|Δx)²/8 with |k|Δx = √dimension · 2π/cells, is left in the measurement.
std::vector<VerifyRow> diagonalLangmuir(int dimension, double wpDt, int cells, const PicDevice& device,
                                        VerifyHistory* history)
{
    requireLeapfrogStable(wpDt);
    std::size_t particles = 1;
    for (int a = 0; a < dimension; ++a)
        particles *= std::size_t(cells);
    const double wp = plasmaFrequency(kDensity), dt = wpDt / wp;
    const double spacing = 1.0 / cells; // m: a 1 m box
    const PeriodicGrid grid(dimension, {cells, cells, dimension == 3 ? cells : 1},
                            {spacing, spacing, dimension == 3 ? spacing : 1.0});
    const std::unique_ptr<PicRun> run =
        device.run(grid, diagonalWaveLattice(grid, 1, kDensity, {1, 0.01 * spacing}), glm::dvec3(0.0), dt);
    const double omega = diagonalWaveFrequency(*run, grid, wpDt, history);
    return rows({setting("wp_dt", wpDt), setting("cells_per_axis", cells), setting("particles", double(particles))},
                device.settings(particles, dimension), {{"omega_over_wp", omega, leapfrogPlasmaFrequency(wpDt)}});
}

} // namespace

std::vector<VerifyRow> verifyLangmuir2D(double wpDt, int cells, const PicDevice& device, VerifyHistory* history)
{
    return diagonalLangmuir(2, wpDt, cells, device, history);
}

std::vector<VerifyRow> verifyLangmuir3D(double wpDt, int cells, const PicDevice& device, VerifyHistory* history)
{
    return diagonalLangmuir(3, wpDt, cells, device, history);
}

std::vector<VerifyRow> verifyBoris(double wcDt, long steps, const PicDevice& device)
{
    requireResolvedGyration(wcDt);
    const double dt = wcDt / cyclotronFrequency(kMagneticField);
    const std::vector<glm::dvec3> v = device.testParticleVelocities({3e5, 0.0, 1e5}, glm::dvec3(0.0),
                                                                    {0.0, 0.0, kMagneticField}, dt, steps);
    const double speed = glm::length(v[0]);
    double angle = 0.0, speedChange = 0.0;
    for (std::size_t n = 1; n < v.size(); ++n) {
        const glm::dvec3 a = v[n - 1], b = v[n];
        angle += std::abs(std::atan2(a.x * b.y - a.y * b.x, a.x * b.x + a.y * b.y));
        speedChange = std::max(speedChange, std::abs(glm::length(b) - speed) / speed);
    }
    return {setting("wc_dt", wcDt), setting("steps", double(steps)),
            {"rotation_per_step_rad", angle / double(steps), borisRotationPerStep(wcDt)},
            {"max_relative_speed_change", speedChange, 0.0}};
}

std::vector<VerifyRow> verifyExB(double wcDt, const PicDevice& device)
{
    requireResolvedGyration(wcDt);
    constexpr long kSteps = 1000;
    const double dt = wcDt / cyclotronFrequency(kMagneticField);
    const glm::dvec3 b(0.0, 0.0, kMagneticField), e(0.5, 0.0, 0.0); // T, V/m: E/B = 1e4 m/s
    const glm::dvec3 drift = glm::cross(e, b) / glm::dot(b, b);
    const double scale = glm::length(e) / glm::length(b);
    // Starting at rest, the electron gyrates about the drift; the Boris velocities lie exactly on a
    // circle about E×B/B² (for any Δt), whose centre is the circumcentre of any three of them.
    const std::vector<glm::dvec3> v = device.testParticleVelocities(glm::dvec3(0.0), e, b, dt, kSteps + 1);
    glm::dvec3 centre(0.0);
    for (long n = 0; n < kSteps; ++n) {
        const glm::dvec3 a = v[n + 1] - v[n], c = v[n + 2] - v[n]; // the circumcentre in the plane ⟂ B
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

std::vector<VerifyRow> verifyTwoStream(double wpDt, const PicDevice& device, VerifyHistory* history)
{
    requireLeapfrogStable(wpDt);
    constexpr int kCells = 256, kPerBeam = 16 * kCells;
    const double kv0 = std::sqrt(3.0 / 8.0); // k v₀/ω_p of the fastest growth
    const double wp = plasmaFrequency(kDensity), dt = wpDt / wp;
    const double v0 = 1e6;                       // m/s
    const double length = 2.0 * physics::kPi * v0 / (kv0 * wp); // mode 1 has k v₀ = kv0·ω_p
    const PeriodicGrid grid(1, {kCells, 1, 1}, {length / kCells, 1.0, 1.0});
    // The seed displacement, 1e-6 of the length: 17 times the relative rounding of a float position
    // (2^-24), so that the rounding a float step adds to every mode stays far below it (a 1e-9 seed
    // measured the rate 1.8% slow on the GPU, the same run in double 0.14% fast).
    const double seed = 1e-6;
    const Perturbation seedWave{1, seed * length};
    Particles beams = quietStart(grid, kPerBeam, 0.5 * kDensity, seedWave, {v0, 0.0, 0.0});
    const Particles backward = quietStart(grid, kPerBeam, 0.5 * kDensity, seedWave, {-v0, 0.0, 0.0});
    beams.position.insert(beams.position.end(), backward.position.begin(), backward.position.end());
    beams.velocity.insert(beams.velocity.end(), backward.velocity.begin(), backward.velocity.end());
    const std::unique_ptr<PicRun> run = device.run(grid, beams, glm::dvec3(0.0), dt);
    // The exponential phase: from 6 to 9 e-foldings of the expected rate after the start, when the
    // growing root dominates the seed's other three and the displacement (8e-3 of the length at the
    // end) is still far below saturation. A history keeps the samples from the start too.
    const double gamma = twoStreamGrowthRate(kv0);
    const double fitStart = 6.0 / gamma;
    const long last = long(std::ceil(9.0 / (gamma * wpDt)));
    // Times in 1/ω_p.
    const ExponentialPhase growth = sampledExponentialPhase(*run, wpDt, fitStart, last, history != nullptr, [&] {
        return std::log(std::abs(fieldMode(run->nodeField(), 1)));
    });
    if (history)
        *history = exponentialHistory("t_wp", "field_mode_V_per_m", growth.t, growth.logAmplitude, fitStart, growth.fit,
                                      gamma);
    return rows({setting("wp_dt", wpDt), setting("cells", kCells), setting("particles", 2 * kPerBeam),
                 setting("k_v0_over_wp", kv0), setting("seed_displacement_over_length", seed)},
                device.settings(2 * kPerBeam, 1), {{"growth_rate_over_wp", growth.fit.slope, gamma}});
}

std::vector<VerifyRow> verifyEnergy(double wpDt, const PicDevice& device, VerifyHistory* history)
{
    requireLeapfrogStable(wpDt);
    constexpr int kCells = 64, kParticles = 64 * kCells;
    constexpr double kPlasmaPeriods = 200.0;
    const double wp = plasmaFrequency(kDensity), dt = wpDt / wp;
    const double thermalSpeed = 4.19e5; // m/s: 1 eV electrons
    const double lambdaD = debyeLength(thermalSpeed, kDensity);
    const PeriodicGrid grid(1, {kCells, 1, 1}, {lambdaD, 1.0, 1.0});
    const std::unique_ptr<PicRun> run =
        device.run(grid, randomStart(grid, kParticles, kDensity, thermalSpeed, 1), glm::dvec3(0.0), dt);
    // The energies at the first and the last step (at every step with a history).
    const long steps = long(std::ceil(kPlasmaPeriods * 2.0 * physics::kPi / wpDt));
    std::vector<long> sampled;
    std::vector<StepEnergies> energies;
    for (long n = 0; n < steps; ++n)
        if (history || n == 0 || n + 1 == steps) {
            sampled.push_back(n);
            energies.push_back(run->stepWithEnergies());
        } else {
            run->step();
        }
    const double initial = energies.front().total(), last = energies.back().total();
    if (history) {
        history->columns = {"t_wp", "kinetic_J_per_m2", "field_J_per_m2", "total_J_per_m2", "relative_change"};
        for (std::size_t i = 0; i < sampled.size(); ++i)
            history->rows.push_back({double(sampled[i]) * wpDt, energies[i].kinetic, energies[i].field,
                                     energies[i].total(), (energies[i].total() - initial) / initial});
        history->fit = {{"relative_drift", (last - initial) / initial}, {"expected_drift", 0.0}};
    }
    return rows({setting("wp_dt", wpDt), setting("dx_over_debye", 1.0), setting("cells", kCells),
                 setting("particles", kParticles), setting("plasma_periods", kPlasmaPeriods)},
                device.settings(kParticles, 1), {{"relative_energy_drift", (last - initial) / initial, 0.0}});
}

std::vector<VerifyRow> verifyHeating(double wpDt, double dxOverDebye, std::uint64_t seed, const PicDevice& device,
                                     int particlesPerCell, VerifyHistory* history)
{
    requireLeapfrogStable(wpDt);
    if (!(dxOverDebye >= kMinHeatingDxDebye && dxOverDebye <= kMaxHeatingDxDebye))
        throw std::domain_error("dx/lambda_D must be in [0.01, 100]");
    if (particlesPerCell < 1)
        throw std::domain_error("particles per cell must be at least 1");
    constexpr int kCells = 64;
    const int particles = particlesPerCell * kCells;
    constexpr double kFitStart = 10.0, kFitEnd = kHeatingRunEndWp; // 1/ω_p: after the start's field has formed
    const double wp = plasmaFrequency(kDensity), dt = wpDt / wp;
    const double thermalSpeed = 4.19e5; // m/s: 1 eV electrons
    const double lambdaD = debyeLength(thermalSpeed, kDensity);
    const PeriodicGrid grid(1, {kCells, 1, 1}, {dxOverDebye * lambdaD, 1.0, 1.0});
    const std::unique_ptr<PicRun> run =
        device.run(grid, randomStart(grid, particles, kDensity, thermalSpeed, seed), glm::dvec3(0.0), dt);
    // kT_x/kT_0 = ⟨v_x²⟩/v_th² at each half step, against ω_p t (from the start with a history).
    std::vector<double> t, temperature;
    const long steps = long(std::ceil(kFitEnd / wpDt));
    for (long n = 0; n < steps; ++n) {
        run->step();
        const double time = (double(n) + 0.5) * wpDt;
        if (time < kFitStart && !history) continue;
        double sum = 0.0;
        for (const glm::dvec3& v : run->velocities())
            sum += v.x * v.x;
        t.push_back(time);
        temperature.push_back(sum / (double(particles) * thermalSpeed * thermalSpeed));
    }
    const Line fit = fittedLine(t, temperature, kFitStart);
    if (history) {
        history->columns = {"t_wp", "kT_x_over_kT0", "in_fit", "fitted"};
        for (std::size_t i = 0; i < t.size(); ++i)
            history->rows.push_back({t[i], temperature[i], t[i] >= kFitStart ? 1.0 : 0.0, fit.at(t[i])});
        history->fit = {{"dx_over_debye", dxOverDebye},
                        {"fit_start", kFitStart},
                        {"fit_end", t.back()},
                        {"fitted_rate", fit.slope},
                        {"fitted_intercept", fit.intercept}};
    }
    return rows({setting("wp_dt", wpDt), setting("dx_over_debye", dxOverDebye), setting("cells", kCells),
                 setting("particles", particles), setting("seed", double(seed))},
                device.settings(particles, 1), {{"heating_rate_over_wp", fit.slope, std::nullopt}});
}

namespace {

// The landau case's field mode s at every step: its zero crossings (linear between steps) and the
// largest |s| between each two (the vertex of the parabola through the three samples around it),
// times in 1/ω_p.
struct LandauPeaks {
    std::vector<double> crossingTime;
    std::vector<double> peakTime, logPeak;
};

// From step firstStep on, up to the last step; s holds steps + 1 samples ω_pΔt = wpDt apart.
LandauPeaks landauPeaks(const std::vector<double>& s, long firstStep, long steps, double wpDt)
{
    LandauPeaks peaks;
    std::vector<long> crossing; // the step before each zero crossing
    for (long n = firstStep; n < steps; ++n)
        if ((s[n] < 0.0) != (s[n + 1] < 0.0)) {
            crossing.push_back(n);
            peaks.crossingTime.push_back((double(n) + s[n] / (s[n] - s[n + 1])) * wpDt);
        }
    for (std::size_t c = 0; c + 1 < crossing.size(); ++c) {
        long best = crossing[c] + 1;
        for (long n = best; n <= crossing[c + 1]; ++n)
            if (std::abs(s[n]) > std::abs(s[best])) best = n;
        // The vertex of the parabola through the three samples, where they bend down about the largest;
        // where they do not (a first sample past the crossing smaller than the one before it, at a
        // coarse ω_pΔt), the sample itself.
        const double a = std::abs(s[best - 1]), b = std::abs(s[best]), d = std::abs(s[best + 1]);
        const double curvature = a - 2.0 * b + d;
        const double offset = b >= a && b >= d && curvature < 0.0 ? 0.5 * (a - d) / curvature : 0.0;
        peaks.peakTime.push_back((double(best) + offset) * wpDt);
        peaks.logPeak.push_back(std::log(b - 0.25 * (a - d) * offset));
    }
    return peaks;
}

// |s| at every step, the maxima (at their interpolated times) and the lines through them: the fitted
// one and the theory's rate γ = root.imag() through the fit's middle.
void writeLandauHistory(VerifyHistory& history, const std::vector<double>& s, long steps, double wpDt,
                        const LandauPeaks& peaks, const Line& fit, std::complex<double> root, double fitStart,
                        double fitEnd, double halfPeriod)
{
    const double middle = 0.5 * (peaks.peakTime.front() + peaks.peakTime.back());
    const Line theory{root.imag(), fit.at(middle) - root.imag() * middle};
    history.columns = {"t_wp", "abs_field_mode", "peak", "fitted", "expected"};
    for (long n = 0; n <= steps; ++n) {
        const double time = double(n) * wpDt;
        history.rows.push_back({time, std::abs(s[n]), kNoValue, std::exp(fit.at(time)), std::exp(theory.at(time))});
    }
    for (std::size_t p = 0; p < peaks.peakTime.size(); ++p)
        history.rows.push_back({peaks.peakTime[p], kNoValue, std::exp(peaks.logPeak[p]),
                                std::exp(fit.at(peaks.peakTime[p])), std::exp(theory.at(peaks.peakTime[p]))});
    std::sort(history.rows.begin(), history.rows.end(),
              [](const std::vector<double>& a, const std::vector<double>& b) { return a[0] < b[0]; });
    history.fit = {{"fit_start", fitStart},
                   {"fit_end", fitEnd},
                   {"fitted_rate", fit.slope},
                   {"fitted_intercept", fit.intercept},
                   {"expected_rate", root.imag()},
                   {"expected_intercept", theory.intercept},
                   {"fitted_omega", physics::kPi / halfPeriod},
                   {"expected_omega", root.real()}};
}

} // namespace

std::vector<VerifyRow> verifyLandau(double wpDt, double kLambda, int particles, const PicDevice& device,
                                    VerifyHistory* history)
{
    requireLeapfrogStable(wpDt);
    if (!(kLambda >= kLandauMinKDebye && kLambda <= kLandauMaxKDebye))
    {
        char range[160];
        std::snprintf(range, sizeof range, "k lambda_D must be in [%g, %g] (got %g)", kLandauMinKDebye,
                      kLandauMaxKDebye, kLambda);
        throw std::domain_error(range);
    }
    constexpr int kCells = 64;
    const double wp = plasmaFrequency(kDensity), dt = wpDt / wp;
    const double thermalSpeed = 4.19e5;
    const double lambdaD = debyeLength(thermalSpeed, kDensity);
    const double length = 2.0 * physics::kPi * lambdaD / kLambda;
    const PeriodicGrid grid(1, {kCells, 1, 1}, {length / kCells, 1.0, 1.0});
    // The density wave δn/n = k·amplitude: small enough that the electrons it traps bounce slower
    // than the wave damps (bounce frequency ω_b = ω_p √(δn/n) below |γ|/√2, so linear theory holds
    // over the run; O'Neil, Phys. Fluids 8, 2255 (1965)), at most 1%.
    const std::complex<double> root = landauRoot(kLambda);
    const double densityWave = std::min(0.01, 2.0 * root.imag() * root.imag());
    const Perturbation wave{1, densityWave * length / (2.0 * physics::kPi)};
    const std::unique_ptr<PicRun> run =
        device.run(grid, quietMaxwellian(grid, particles, kDensity, wave, thermalSpeed), glm::dvec3(0.0), dt);
    // The standing wave's field mode s(t) ∝ exp(γt) cos(ωt + φ) over a window (in 1/ω_p) from where
    // the free-streaming part, ∝ exp(−(kλ_D ω_p t)²/2), has fallen below 1% of the wave,
    // t₀ = √(2 ln 100)/(kλ_D), to where the theory's damping has taken 2.1 e-foldings (the wave, 1% at
    // the start so that it stays linear, then nears the particles' noise), at most 60/ω_p and at least
    // 3 periods: at kλ_D = 0.5 from 6.1 to 19.8. Its zero crossings (linear between steps) are π/ω
    // apart, and the logarithm of its largest |s| between two crossings (the parabola through the
    // three samples around it) grows at the rate γ.
    const double fitStart = std::sqrt(2.0 * std::log(100.0)) / kLambda;
    const double fitEnd =
        fitStart + std::clamp(2.1 / std::abs(root.imag()), 3.0 * 2.0 * physics::kPi / root.real(), 60.0);
    std::vector<double> s;
    const long steps = long(std::ceil(fitEnd / wpDt));
    for (long n = 0; n <= steps; ++n) {
        s.push_back(fieldMode(run->nodeField(), 1).imag()); // the field of a cos(kx) density wave ∝ sin(kx)
        run->step();
    }
    const LandauPeaks peaks = landauPeaks(s, long(std::ceil(fitStart / wpDt)), steps, wpDt);
    if (peaks.peakTime.size() < 3)
        throw std::runtime_error("landau: fewer than four zero crossings of the field");
    const double halfPeriod =
        (peaks.crossingTime.back() - peaks.crossingTime.front()) / double(peaks.crossingTime.size() - 1);
    const Line fit = fittedLine(peaks.peakTime, peaks.logPeak);
    if (history)
        writeLandauHistory(*history, s, steps, wpDt, peaks, fit, root, fitStart, fitEnd, halfPeriod);
    return rows({setting("wp_dt", wpDt), setting("k_debye", kLambda), setting("cells", kCells),
                 setting("particles", particles)},
                device.settings(particles, 1),
                {{"frequency_over_wp", physics::kPi / halfPeriod, root.real()}, {"damping_rate_over_wp", fit.slope, root.imag()}});
}

std::vector<VerifyRow> verifyDiocotron(double wcDt, double wpOverWc, const PicDevice& device, VerifyHistory* history)
{
    requireResolvedGyration(wcDt);
    if (!(wpOverWc > 0.0 && wpOverWc < 1.0))
        throw std::domain_error("omega_p/omega_c must be in (0, 1): the guiding-centre regime");
    requireLeapfrogStable(wpOverWc * wcDt);
    constexpr double kHalfThickness = 0.4; // ka: near the fastest growth, 0.2012 ω_D for L → ∞
    ElectronSheetSpec spec;
    spec.cellsAlong = 128;
    spec.cellsAcross = 64;
    spec.lengthM = 128.0; // 1 m cells: a cold drift flow has no length scale of its own
    spec.widthM = 64.0;
    const double k = 2.0 * physics::kPi / spec.lengthM;
    spec.thicknessM = 2.0 * kHalfThickness / k;
    spec.magneticFieldT = kMagneticField;
    const double wp = wpOverWc * cyclotronFrequency(kMagneticField);
    spec.electronDensity = wp * wp * kVacuumPermittivity * kElectronMass / (kElementaryCharge * kElementaryCharge);
    spec.cyclotronFrequencyTimesDt = wcDt;
    // 1e-5 a: ten times the rounding of a float position at the box's far side (7.6e-6 m at 64 m,
    // 1e-6 a), so that the rounding a float step adds stays far below the seed.
    spec.seedDisplacementM = 1e-5 * 0.5 * spec.thicknessM;
    const PeriodicGrid grid = sheetGrid(spec);
    const Particles electrons = sheetElectrons(spec);
    const std::unique_ptr<PicRun> run =
        device.run(grid, electrons, {0.0, 0.0, spec.magneticFieldT}, sheetTimeStep(spec));
    const double expected = diocotronGrowthRate(kHalfThickness, k * spec.widthM);
    const double wdDt = diocotronFrequency(spec) * sheetTimeStep(spec);
    // The mode's field energy Σ_y |Ê(k, y)|², Ê the x-transform of both components at mode 1.
    const int nx = grid.cells[0], ny = grid.cells[1];
    std::vector<std::complex<double>> phase(nx);
    for (int i = 0; i < nx; ++i)
        phase[i] = std::polar(1.0, -2.0 * physics::kPi * i / nx);
    const auto modeEnergy = [&] {
        const std::vector<glm::dvec3>& field = run->nodeField();
        double sum = 0.0;
        for (int j = 0; j < ny; ++j) {
            std::complex<double> ex = 0.0, ey = 0.0;
            for (int i = 0; i < nx; ++i) {
                const glm::dvec3& e = field[grid.index(i, j, 0)];
                ex += e.x * phase[i];
                ey += e.y * phase[i];
            }
            sum += std::norm(ex) + std::norm(ey);
        }
        return sum;
    };
    // The amplitude ½ ln W from 4 to 7 e-foldings of the expected rate: the decaying root of the
    // seed has fallen to e^-8 of the growing one, and the displacement (1e-5 a at the start) stays
    // below 0.011 a, linear. A history keeps the samples from the start too.
    const double fitStart = 4.0 / expected;
    const long last = long(std::ceil(7.0 / (expected * wdDt)));
    // Times in 1/ω_D.
    const ExponentialPhase growth = sampledExponentialPhase(*run, wdDt, fitStart, last, history != nullptr, [&] {
        return 0.5 * std::log(modeEnergy());
    });
    if (history)
        *history = exponentialHistory("t_wd", "mode_amplitude", growth.t, growth.logAmplitude, fitStart, growth.fit,
                                      expected);
    const std::size_t particles = electrons.position.size();
    return rows({setting("wc_dt", wcDt), setting("wp_dt", wpOverWc * wcDt), setting("wp_over_wc", wpOverWc),
                 setting("k_a", kHalfThickness), setting("cells", double(nx) * ny),
                 setting("particles", double(particles)), setting("steps", double(last)),
                 setting("seed_displacement_over_a", 1e-5)},
                device.settings(particles, 2), {{"growth_rate_over_wd", growth.fit.slope, expected}});
}

} // namespace aurorawall::components::plasma::simulation
