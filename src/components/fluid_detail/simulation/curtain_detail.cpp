#include "components/fluid_detail/simulation/curtain_detail.h"

#include "physics/constants.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace aurorawall::components::fluid_detail::simulation {

namespace {

void require(bool ok, const std::string& what)
{
    if (!ok)
        throw std::invalid_argument("curtain detail spec: " + what);
}

void validate(const CurtainDetailSpec& s)
{
    require(isPowerOfTwo(s.nx) && isPowerOfTwo(s.ny) && s.nx >= 4 && s.ny >= 4, "nx and ny must be powers of two >= 4");
    require(s.stripLengthKm > 0.0 && s.stripWidthKm > 0.0, "strip length and width must be positive");
    const double aspect = (s.stripLengthKm / s.nx) / (s.stripWidthKm / s.ny);
    require(aspect >= 0.5 && aspect <= 2.0, "cells must be near square (texel length / width in [1/2, 2])");
    require(s.shearThicknessKm > 0.0 && s.fluxWidthKm > 0.0, "shear thickness and flux width must be positive");
    require(s.frames >= 1 && s.stepsPerFrame >= 1, "frames and steps per frame must be >= 1");
    require(s.timeBetweenFramesS >= 0.0, "time between frames must be >= 0");
    require(s.multigridCycles >= 1 && s.multigridTolerance > 0.0, "multigrid cycles >= 1 and tolerance > 0");
}

// SplitMix64 (Steele, Lea & Flood 2014): z ← z + 0x9E3779B97F4A7C15, then xor-shift-multiply;
// its top 53 bits as a double in [0, 1). Integer arithmetic only, so the same on every platform.
double hashUnit(std::uint64_t key)
{
    std::uint64_t z = key + 0x9E3779B97F4A7C15ull;
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    z ^= z >> 31;
    return double(z >> 11) * 0x1.0p-53;
}

} // namespace

// Initial condition, y' = y − Ly/2 in [−Ly/2, Ly/2]:
//   u = U [tanh(y'/δ) − (2y'/Ly) tanh(Ly/(2δ))]   tanh shear layer plus a uniform return shear
//       (zero at y' = ±Ly/2, so u is continuous and periodic; a linear profile has no inflection
//       point, so by Rayleigh's criterion only the central layer is unstable);
//   v = (ε U/√M) Σₘ aₘ sin(2π m x/Lx + φₘ) exp(−(y'/2δ)²), m = 1..M, M = max(1, ⌊Lx/(4δ)⌋)
//       (every wavelength ≥ 4δ, including the fastest-growing one, 2π δ/0.44 ≈ 14 δ
//       [Michalke 1964]), aₘ in [½, 1) and φₘ in [0, 2π) from hashUnit(seed, m);
//   F = exp(−y'²/(2σ²)) / Σⱼ exp(−y'ⱼ²/(2σ²)) hy   (∫F dy = 1 per column, discretely).
CurtainFlow::CurtainFlow(const CurtainDetailSpec& spec)
{
    validate(spec);
    settings_.maxCycles = spec.multigridCycles;
    settings_.tolerance = spec.multigridTolerance;
    const double hx = spec.stripLengthKm / spec.nx;
    const double hy = spec.stripWidthKm / spec.ny;
    if (spec.pressureSolver == PressureSolver::Fft)
        fft_.emplace(spec.nx, spec.ny, hx, hy);
    const double lx = spec.stripLengthKm;
    const double ly = spec.stripWidthKm;
    const double delta = spec.shearThicknessKm;
    const double U = spec.shearVelocity;
    velocity_ = {PeriodicField(spec.nx, spec.ny, hx, hy), PeriodicField(spec.nx, spec.ny, hx, hy)};
    phi_ = PeriodicField(spec.nx, spec.ny, hx, hy);
    flux_ = PeriodicField(spec.nx, spec.ny, hx, hy);

    for (int j = 0; j < spec.ny; ++j) {
        const double y = (j + 0.5) * hy - 0.5 * ly;
        const double u = U * (std::tanh(y / delta) - (2.0 * y / ly) * std::tanh(0.5 * ly / delta));
        for (int i = 0; i < spec.nx; ++i)
            velocity_.u(i, j) = u;
    }

    const int modes = std::max(1, int(lx / (2.0 * physics::kPi * delta)));
    std::vector<double> amplitude(modes);
    std::vector<double> phase(modes);
    for (int m = 0; m < modes; ++m) {
        const std::uint64_t key = (std::uint64_t(spec.seed) << 32) | std::uint64_t(m);
        amplitude[m] = 0.5 + 0.5 * hashUnit(2 * key);
        phase[m] = 2.0 * physics::kPi * hashUnit(2 * key + 1);
    }
    const double scale = spec.perturbation * U / std::sqrt(double(modes));
    for (int i = 0; i < spec.nx; ++i) {
        const double x = (i + 0.5) * hx;
        double sum = 0.0;
        for (int m = 0; m < modes; ++m)
            sum += amplitude[m] * std::sin(2.0 * physics::kPi * (m + 1) * x / lx + phase[m]);
        for (int j = 0; j < spec.ny; ++j) {
            const double y = j * hy - 0.5 * ly;
            const double envelope = std::exp(-(y / (2.0 * delta)) * (y / (2.0 * delta)));
            velocity_.v(i, j) = scale * sum * envelope;
        }
    }
    project();

    std::vector<double> profile(spec.ny);
    double column = 0.0;
    for (int j = 0; j < spec.ny; ++j) {
        const double y = (j + 0.5) * hy - 0.5 * ly;
        profile[j] = std::exp(-0.5 * (y / spec.fluxWidthKm) * (y / spec.fluxWidthKm));
        column += profile[j] * hy;
    }
    for (int j = 0; j < spec.ny; ++j)
        for (int i = 0; i < spec.nx; ++i)
            flux_(i, j) = profile[j] / column;
}

std::optional<MultigridReport> CurtainFlow::step(double dt)
{
    advectScalar(flux_, velocity_, dt);
    advectVelocity(velocity_, dt);
    return project();
}

std::optional<MultigridReport> CurtainFlow::project()
{
    if (fft_) {
        simulation::project(velocity_, phi_, *fft_);
        return std::nullopt;
    }
    return simulation::project(velocity_, phi_, settings_);
}

double CurtainFlow::crossStreamEnergy() const
{
    const PeriodicField& v = velocity_.v;
    double sum = 0.0;
    for (double q : v.values)
        sum += q * q;
    return 0.5 * sum * v.hx * v.hy;
}

roles::FluxFrames simulateCurtainDetail(const CurtainDetailSpec& spec)
{
    CurtainFlow flow(spec);
    roles::FluxFrames out;
    out.nx = spec.nx;
    out.ny = spec.ny;
    out.frames = spec.frames;
    out.texelKmX = float(spec.stripLengthKm / spec.nx);
    out.texelKmY = float(spec.stripWidthKm / spec.ny);
    out.flux.reserve(std::size_t(spec.frames) * spec.nx * spec.ny);
    const double dt = spec.timeBetweenFramesS / spec.stepsPerFrame;
    for (int k = 0; k < spec.frames; ++k) {
        if (k > 0)
            for (int n = 0; n < spec.stepsPerFrame; ++n)
                flow.step(dt);
        for (double q : flow.flux().values)
            out.flux.push_back(float(q));
    }
    return out;
}

} // namespace aurorawall::components::fluid_detail::simulation
