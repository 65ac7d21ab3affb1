#include "components/plasma/simulation/verify_cases.h"

#include "common/constants.h"
#include "common/glsl.h"
#include "components/plasma/simulation/dispersion.h"
#include "components/plasma/simulation/electron_sheet.h"
#include "components/plasma/simulation/electrostatic_pic.h"
#include "components/plasma/simulation/particle_loading.h"
#include "components/plasma/simulation/plasma_parameters.h"

#include <glm/geometric.hpp>

#include <cmath>
#include <complex>
#include <stdexcept>

// The push in double (a named namespace: not every function is used here).
namespace aurorawall::plasma::verify_f64 {
AURORAWALL_GLSL_PRECISION(double)
#include "components/plasma/boris_push.glsl"
} // namespace aurorawall::plasma::verify_f64

namespace aurorawall::plasma {
namespace {
namespace f64 = verify_f64;

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
std::complex<double> fieldMode(const ElectrostaticPic& pic, int mode)
{
    const std::vector<glm::dvec3>& e = pic.nodeField();
    const int n = pic.grid().cells[0];
    std::complex<double> sum = 0.0;
    for (int j = 0; j < n; ++j)
        sum += e[j].x * std::polar(1.0, -2.0 * kPi * mode * j / n);
    return sum * (2.0 / n);
}

// The slope of the least-squares line through (t, y).
double fittedSlope(const std::vector<double>& t, const std::vector<double>& y)
{
    double mt = 0.0, my = 0.0;
    for (std::size_t i = 0; i < t.size(); ++i) {
        mt += t[i];
        my += y[i];
    }
    mt /= double(t.size());
    my /= double(y.size());
    double stt = 0.0, sty = 0.0;
    for (std::size_t i = 0; i < t.size(); ++i) {
        stt += (t[i] - mt) * (t[i] - mt);
        sty += (t[i] - mt) * (y[i] - my);
    }
    return sty / stt;
}

void requireLeapfrogStable(double wpDt)
{
    if (!(wpDt > 0.0 && wpDt < 2.0))
        throw std::domain_error("omega_p dt must be in (0, 2): the leapfrog is unstable from 2 on");
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

double VerifyRow::relativeError() const
{
    const double e = expected.value_or(0.0);
    return e != 0.0 ? std::abs(measured - e) / std::abs(e) : std::abs(measured - e);
}

std::vector<VerifyRow> verifyLangmuir(double wpDt)
{
    requireLeapfrogStable(wpDt);
    // Mode 1 on 1024 cells: kΔx = 0.006, so the grid's own dispersion (a relative −(kΔx)²/8 in ω) stays
    // below 1e-5; 8 cold particles per cell, displaced by a hundredth of a cell.
    constexpr int kCells = 1024, kParticles = 8 * kCells;
    const double wp = plasmaFrequency(kDensity), dt = wpDt / wp;
    const double length = 1.0; // m; a cold plasma has no length scale of its own
    const PeriodicGrid grid(1, {kCells, 1, 1}, {length / kCells, 1.0, 1.0});
    ElectrostaticPic pic(grid, quietStart(grid, kParticles, kDensity, {1, 0.01 * length / kCells}, glm::dvec3(0.0)),
                         glm::dvec3(0.0), dt);
    // The field mode over 20 plasma periods.
    std::vector<double> s;
    const long steps = long(std::ceil(20 * 2.0 * kPi / wpDt));
    for (long n = 0; n <= steps; ++n) {
        s.push_back(fieldMode(pic, 1).imag());
        pic.step();
    }
    const double omegaDt = sampledCosineFrequency(s);
    return {setting("wp_dt", wpDt), setting("cells", kCells), setting("particles", kParticles),
            {"omega_over_wp", omegaDt / wpDt, leapfrogPlasmaFrequency(wpDt)}};
}

std::vector<VerifyRow> verifyLangmuir2D(double wpDt, int kCells)
{
    requireLeapfrogStable(wpDt);
    // Mode (1, 1) on kCells² cells, one cold particle per cell displaced along the diagonal by a
    // hundredth of a cell. The grid's dispersion is now −(kΔx)²/8 per axis with kΔx = 2π/kCells
    // (about 1e-4 for 256 cells).
    const int kParticles = kCells * kCells;
    const double wp = plasmaFrequency(kDensity), dt = wpDt / wp;
    const double length = 1.0; // m
    const double spacing = length / kCells;
    const PeriodicGrid grid(2, {kCells, kCells, 1}, {spacing, spacing, 1.0});
    ElectrostaticPic pic(grid, diagonalWaveLattice(grid, 1, kDensity, {1, 0.01 * spacing}), glm::dvec3(0.0), dt);
    // The mode's field along the diagonal: Σ_ij (E_x + E_y)/√2 · exp(−i k·x_ij) (up to a constant
    // factor), sin-like as in 1D; the phase depends on (i + j) mod n only.
    std::vector<std::complex<double>> phase(kCells);
    for (int m = 0; m < kCells; ++m)
        phase[m] = std::polar(1.0, -2.0 * kPi * m / kCells);
    const auto diagonalMode = [&pic, &phase, kCells] {
        const std::vector<glm::dvec3>& e = pic.nodeField();
        std::complex<double> sum = 0.0;
        for (int j = 0; j < kCells; ++j)
            for (int i = 0; i < kCells; ++i) {
                const glm::dvec3& node = e[pic.grid().index(i, j, 0)];
                sum += (node.x + node.y) * phase[(i + j) % kCells];
            }
        return sum.imag();
    };
    std::vector<double> s;
    const long steps = long(std::ceil(20 * 2.0 * kPi / wpDt));
    for (long n = 0; n <= steps; ++n) {
        s.push_back(diagonalMode());
        pic.step();
    }
    const double omegaDt = sampledCosineFrequency(s);
    return {setting("wp_dt", wpDt), setting("cells_per_axis", kCells), setting("particles", kParticles),
            {"omega_over_wp", omegaDt / wpDt, leapfrogPlasmaFrequency(wpDt)}};
}

std::vector<VerifyRow> verifyBoris(double wcDt, long steps)
{
    if (!(wcDt > 0.0) || !std::isfinite(wcDt))
        throw std::domain_error("omega_c dt must be a finite number > 0");
    const double dt = wcDt / cyclotronFrequency(kMagneticField);
    const glm::dvec3 b(0.0, 0.0, kMagneticField);
    glm::dvec3 v(3e5, 0.0, 1e5);
    const double speed = glm::length(v);
    double angle = 0.0, speedChange = 0.0;
    for (long n = 0; n < steps; ++n) {
        const glm::dvec3 next = f64::borisVelocity(v, glm::dvec3(0.0), b, kChargeOverMass, dt);
        angle += std::abs(std::atan2(v.x * next.y - v.y * next.x, v.x * next.x + v.y * next.y));
        v = next;
        speedChange = std::max(speedChange, std::abs(glm::length(v) - speed) / speed);
    }
    return {setting("wc_dt", wcDt), setting("steps", double(steps)),
            {"rotation_per_step_rad", angle / double(steps), borisRotationPerStep(wcDt)},
            {"max_relative_speed_change", speedChange, 0.0}};
}

std::vector<VerifyRow> verifyExB(double wcDt)
{
    if (!(wcDt > 0.0) || !std::isfinite(wcDt))
        throw std::domain_error("omega_c dt must be a finite number > 0");
    constexpr long kSteps = 1000;
    const double dt = wcDt / cyclotronFrequency(kMagneticField);
    const glm::dvec3 b(0.0, 0.0, kMagneticField), e(0.5, 0.0, 0.0); // T, V/m: E/B = 1e4 m/s
    const glm::dvec3 drift = glm::cross(e, b) / glm::dot(b, b);
    const double scale = glm::length(e) / glm::length(b);
    // Starting at rest, the electron gyrates about the drift; the Boris velocities lie exactly on a
    // circle about E×B/B² (for any Δt), whose centre is the circumcentre of any three of them.
    glm::dvec3 v0(0.0), v1 = f64::borisVelocity(v0, e, b, kChargeOverMass, dt);
    glm::dvec3 centre(0.0);
    for (long n = 0; n < kSteps; ++n) {
        const glm::dvec3 v2 = f64::borisVelocity(v1, e, b, kChargeOverMass, dt);
        const glm::dvec3 a = v1 - v0, c = v2 - v0; // the circumcentre in the plane ⟂ B
        const double d = 2.0 * (a.x * c.y - a.y * c.x);
        const double aa = glm::dot(a, a), cc = glm::dot(c, c);
        centre += v0 + glm::dvec3((c.y * aa - a.y * cc) / d, (a.x * cc - c.x * aa) / d, 0.0);
        v0 = v1;
        v1 = v2;
    }
    centre /= double(kSteps);
    const glm::dvec3 alongDrift = drift / glm::length(drift), alongE = e / glm::length(e);
    return {setting("wc_dt", wcDt), setting("steps", double(kSteps)),
            {"drift_along_ExB_over_E_over_B", glm::dot(centre, alongDrift) / scale, glm::length(drift) / scale},
            {"drift_along_E_over_E_over_B", glm::dot(centre, alongE) / scale, glm::dot(drift, alongE) / scale}};
}

std::vector<VerifyRow> verifyTwoStream(double wpDt)
{
    requireLeapfrogStable(wpDt);
    constexpr int kCells = 256, kPerBeam = 16 * kCells;
    const double kv0 = std::sqrt(3.0 / 8.0); // k v₀/ω_p of the fastest growth
    const double wp = plasmaFrequency(kDensity), dt = wpDt / wp;
    const double v0 = 1e6;                       // m/s
    const double length = 2.0 * kPi * v0 / (kv0 * wp); // mode 1 has k v₀ = kv0·ω_p
    const PeriodicGrid grid(1, {kCells, 1, 1}, {length / kCells, 1.0, 1.0});
    const Perturbation seedWave{1, 1e-9 * length};
    Particles beams = quietStart(grid, kPerBeam, 0.5 * kDensity, seedWave, {v0, 0.0, 0.0});
    const Particles backward = quietStart(grid, kPerBeam, 0.5 * kDensity, seedWave, {-v0, 0.0, 0.0});
    beams.position.insert(beams.position.end(), backward.position.begin(), backward.position.end());
    beams.velocity.insert(beams.velocity.end(), backward.velocity.begin(), backward.velocity.end());
    ElectrostaticPic pic(grid, beams, glm::dvec3(0.0), dt);
    // The exponential phase: from 6 to 16 e-foldings of the expected rate after the start, when the
    // growing root dominates the seed's other three and the amplitude is still far below saturation.
    const double gamma = twoStreamGrowthRate(kv0);
    std::vector<double> t, logAmplitude;
    const long last = long(std::ceil(16.0 / (gamma * wpDt)));
    for (long n = 0; n <= last; ++n) {
        const double time = n * wpDt; // in 1/ω_p
        if (time >= 6.0 / gamma) {
            t.push_back(time);
            logAmplitude.push_back(std::log(std::abs(fieldMode(pic, 1))));
        }
        pic.step();
    }
    return {setting("wp_dt", wpDt), setting("cells", kCells), setting("particles", 2 * kPerBeam),
            setting("k_v0_over_wp", kv0), {"growth_rate_over_wp", fittedSlope(t, logAmplitude), gamma}};
}

std::vector<VerifyRow> verifyEnergy(double wpDt)
{
    requireLeapfrogStable(wpDt);
    constexpr int kCells = 64, kParticles = 64 * kCells;
    constexpr double kPlasmaPeriods = 200.0;
    const double wp = plasmaFrequency(kDensity), dt = wpDt / wp;
    const double thermalSpeed = 4.19e5; // m/s: 1 eV electrons
    const double lambdaD = debyeLength(thermalSpeed, kDensity);
    const PeriodicGrid grid(1, {kCells, 1, 1}, {lambdaD, 1.0, 1.0});
    ElectrostaticPic pic(grid, randomStart(grid, kParticles, kDensity, thermalSpeed, 1), glm::dvec3(0.0), dt);
    const long steps = long(std::ceil(kPlasmaPeriods * 2.0 * kPi / wpDt));
    const double initial = pic.step().total();
    double last = initial;
    for (long n = 1; n < steps; ++n)
        last = pic.step().total();
    return {setting("wp_dt", wpDt), setting("dx_over_debye", 1.0), setting("cells", kCells),
            setting("particles", kParticles), setting("plasma_periods", kPlasmaPeriods),
            {"relative_energy_drift", (last - initial) / initial, 0.0}};
}

std::vector<VerifyRow> verifyHeating(double wpDt, double dxOverDebye, std::uint64_t seed, ParticleShape shape,
                                     int particlesPerCell)
{
    requireLeapfrogStable(wpDt);
    if (!(dxOverDebye > 0.0) || !std::isfinite(dxOverDebye))
        throw std::domain_error("dx/lambda_D must be a finite number > 0");
    if (particlesPerCell < 1)
        throw std::domain_error("particles per cell must be at least 1");
    constexpr int kCells = 64;
    const int particles = particlesPerCell * kCells;
    constexpr double kFitStart = 10.0, kFitEnd = 200.0; // 1/ω_p: after the start's field has formed
    const double wp = plasmaFrequency(kDensity), dt = wpDt / wp;
    const double thermalSpeed = 4.19e5; // m/s: 1 eV electrons
    const double lambdaD = debyeLength(thermalSpeed, kDensity);
    const PeriodicGrid grid(1, {kCells, 1, 1}, {dxOverDebye * lambdaD, 1.0, 1.0});
    ElectrostaticPic pic(grid, randomStart(grid, particles, kDensity, thermalSpeed, seed), glm::dvec3(0.0), dt,
                         shape);
    // kT_x/kT_0 = ⟨v_x²⟩/v_th² at each half step, against ω_p t.
    std::vector<double> t, temperature;
    const long steps = long(std::ceil(kFitEnd / wpDt));
    for (long n = 0; n < steps; ++n) {
        pic.step();
        const double time = (double(n) + 0.5) * wpDt;
        if (time < kFitStart) continue;
        double sum = 0.0;
        for (const glm::dvec3& v : pic.electrons().velocity)
            sum += v.x * v.x;
        t.push_back(time);
        temperature.push_back(sum / (double(particles) * thermalSpeed * thermalSpeed));
    }
    return {setting("wp_dt", wpDt), setting("dx_over_debye", dxOverDebye), setting("cells", kCells),
            setting("particles", particles), setting("seed", double(seed)),
            {"heating_rate_over_wp", fittedSlope(t, temperature), std::nullopt}};
}

std::vector<VerifyRow> verifyLandau(double wpDt)
{
    requireLeapfrogStable(wpDt);
    constexpr double kLambda = 0.5; // k λ_D
    constexpr int kCells = 64, kParticles = 1 << 20;
    const double wp = plasmaFrequency(kDensity), dt = wpDt / wp;
    const double thermalSpeed = 4.19e5;
    const double lambdaD = debyeLength(thermalSpeed, kDensity);
    const double length = 2.0 * kPi * lambdaD / kLambda;
    const PeriodicGrid grid(1, {kCells, 1, 1}, {length / kCells, 1.0, 1.0});
    // A 1% density perturbation: δn/n = k·amplitude.
    const Perturbation wave{1, 0.01 * length / (2.0 * kPi)};
    ElectrostaticPic pic(grid, quietMaxwellian(grid, kParticles, kDensity, wave, thermalSpeed), glm::dvec3(0.0), dt);
    // The standing wave's field mode s(t) ∝ exp(γt) cos(ωt + φ) from 6 to 20 /ω_p (before 6 the
    // free-streaming part, ∝ exp(−(k v_th t)²/2), is still above 1%; after 20 the wave nears the
    // particles' noise, a 1% wave being linear, a 5% one not quite): its zero crossings
    // (linear between steps) are π/ω apart, and the logarithm of its largest |s| between two crossings
    // (the parabola through the three samples around it) grows at the rate γ.
    std::vector<double> s;
    const long steps = long(std::ceil(20.0 / wpDt));
    for (long n = 0; n <= steps; ++n) {
        s.push_back(fieldMode(pic, 1).imag()); // the field of a cos(kx) density wave ∝ sin(kx)
        pic.step();
    }
    std::vector<long> crossing;      // the step before each zero crossing
    std::vector<double> crossingTime; // in 1/ω_p
    for (long n = long(std::ceil(6.0 / wpDt)); n < steps; ++n)
        if ((s[n] < 0.0) != (s[n + 1] < 0.0)) {
            crossing.push_back(n);
            crossingTime.push_back((double(n) + s[n] / (s[n] - s[n + 1])) * wpDt);
        }
    std::vector<double> peakTime, logPeak;
    for (std::size_t c = 0; c + 1 < crossing.size(); ++c) {
        long best = crossing[c] + 1;
        for (long n = best; n <= crossing[c + 1]; ++n)
            if (std::abs(s[n]) > std::abs(s[best])) best = n;
        const double a = std::abs(s[best - 1]), b = std::abs(s[best]), d = std::abs(s[best + 1]);
        const double offset = 0.5 * (a - d) / (a - 2.0 * b + d);
        peakTime.push_back((double(best) + offset) * wpDt);
        logPeak.push_back(std::log(b - 0.25 * (a - d) * offset));
    }
    if (peakTime.size() < 3)
        throw std::runtime_error("landau: fewer than four zero crossings of the field");
    const double halfPeriod = (crossingTime.back() - crossingTime.front()) / double(crossingTime.size() - 1);
    const std::complex<double> root = landauRoot(kLambda);
    return {setting("wp_dt", wpDt), setting("k_debye", kLambda), setting("cells", kCells),
            setting("particles", kParticles),
            {"frequency_over_wp", kPi / halfPeriod, root.real()},
            {"damping_rate_over_wp", fittedSlope(peakTime, logPeak), root.imag()}};
}

std::vector<VerifyRow> verifyDiocotron(double wcDt, double wpOverWc)
{
    if (!(wcDt > 0.0) || !std::isfinite(wcDt))
        throw std::domain_error("omega_c dt must be a finite number > 0");
    if (!(wpOverWc > 0.0 && wpOverWc < 1.0))
        throw std::domain_error("omega_p/omega_c must be in (0, 1): the guiding-centre regime");
    requireLeapfrogStable(wpOverWc * wcDt);
    constexpr double kHalfThickness = 0.4; // ka: near the fastest growth, 0.2012 ω_D for L → ∞
    ElectronSheetSpec spec;
    spec.cellsAlong = 128;
    spec.cellsAcross = 64;
    spec.lengthM = 128.0; // 1 m cells: a cold drift flow has no length scale of its own
    spec.widthM = 64.0;
    const double k = 2.0 * kPi / spec.lengthM;
    spec.thicknessM = 2.0 * kHalfThickness / k;
    spec.magneticFieldT = kMagneticField;
    const double wp = wpOverWc * cyclotronFrequency(kMagneticField);
    spec.electronDensity = wp * wp * kVacuumPermittivity * kElectronMass / (kElementaryCharge * kElementaryCharge);
    spec.cyclotronFrequencyTimesDt = wcDt;
    spec.seedDisplacementM = 1e-8 * 0.5 * spec.thicknessM;
    ElectrostaticPic pic = sheetSimulation(spec);
    const double expected = diocotronGrowthRate(kHalfThickness, k * spec.widthM);
    const double wdDt = diocotronFrequency(spec) * sheetTimeStep(spec);
    // The mode's field energy Σ_y |Ê(k, y)|², Ê the x-transform of both components at mode 1.
    const PeriodicGrid& grid = pic.grid();
    const int nx = grid.cells[0], ny = grid.cells[1];
    std::vector<std::complex<double>> phase(nx);
    for (int i = 0; i < nx; ++i)
        phase[i] = std::polar(1.0, -2.0 * kPi * i / nx);
    const auto modeEnergy = [&] {
        double sum = 0.0;
        for (int j = 0; j < ny; ++j) {
            std::complex<double> ex = 0.0, ey = 0.0;
            for (int i = 0; i < nx; ++i) {
                const glm::dvec3& e = pic.nodeField()[grid.index(i, j, 0)];
                ex += e.x * phase[i];
                ey += e.y * phase[i];
            }
            sum += std::norm(ex) + std::norm(ey);
        }
        return sum;
    };
    // The amplitude ½ ln W from 4 to 14 e-foldings of the expected rate: the decaying root of the
    // seed has fallen to e^-8 of the growing one, and the displacement (1e-8 a at the start) stays
    // below 0.02 a, linear.
    std::vector<double> t, logAmplitude;
    const long last = long(std::ceil(14.0 / (expected * wdDt)));
    for (long n = 0; n <= last; ++n) {
        const double time = n * wdDt; // in 1/ω_D
        if (time >= 4.0 / expected) {
            t.push_back(time);
            logAmplitude.push_back(0.5 * std::log(modeEnergy()));
        }
        pic.step();
    }
    return {setting("wc_dt", wcDt), setting("wp_dt", wpOverWc * wcDt), setting("wp_over_wc", wpOverWc),
            setting("k_a", kHalfThickness), setting("cells", double(nx) * ny),
            setting("particles", double(pic.electrons().position.size())), setting("steps", double(last)),
            {"growth_rate_over_wd", fittedSlope(t, logAmplitude), expected}};
}

} // namespace aurorawall::plasma
