// The curtain-detail simulation: flux bounds and conservation, Kelvin–Helmholtz growth from a
// smooth start to a structured end, divergence after each step, bit-for-bit determinism, and the
// periodic frame sampler.
#include "components/fluid_detail/simulation/curtain_detail.h"
#include "flow_metrics.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <cstring>
#include <optional>
#include <stdexcept>
#include <utility>
#include <vector>

namespace aurorawall::components::fluid_detail::simulation {
namespace {

using roles::FluxFrames;
using roles::sampleFlux;

// Flux per unit length along the strip: (1/Lx) ∫∫ F dA; 1 at frame 0 by construction.
double fluxPerLength(const PeriodicField& f)
{
    double sum = 0.0;
    for (double q : f.values)
        sum += q;
    return sum * f.hy / f.nx;
}

// The flux-weighted centre line across the strip, column by column: y_c = Σ y' F / Σ F.
std::vector<double> centreLine(const PeriodicField& f)
{
    std::vector<double> yc(f.nx);
    for (int i = 0; i < f.nx; ++i) {
        double moment = 0.0, mass = 0.0;
        for (int j = 0; j < f.ny; ++j) {
            const double y = (j + 0.5 - 0.5 * f.ny) * f.hy;
            moment += y * f(i, j);
            mass += f(i, j);
        }
        yc[i] = moment / mass;
    }
    return yc;
}

double varianceAlongX(const std::vector<double>& values)
{
    double mean = 0.0;
    for (double q : values)
        mean += q;
    mean /= double(values.size());
    double variance = 0.0;
    for (double q : values)
        variance += (q - mean) * (q - mean);
    return variance / double(values.size());
}

// Σ_j hy Σ_i |F(i+1, j) − F(i, j)| / Lx: total variation along the curtain per unit length.
double totalVariationAlongX(const PeriodicField& f)
{
    double tv = 0.0;
    for (int j = 0; j < f.ny; ++j)
        for (int i = 0; i < f.nx; ++i)
            tv += std::abs(f(i + 1, j) - f(i, j));
    return tv * f.hy / (f.nx * f.hx);
}

TEST(CurtainDetail, FluxStaysBoundedAndNearlyConservedOverTheDefaultRun)
{
    const CurtainDetailSpec spec;
    CurtainFlow flow(spec);
    const double max0 = *std::max_element(flow.flux().values.begin(), flow.flux().values.end());
    EXPECT_NEAR(fluxPerLength(flow.flux()), 1.0, 1e-12);
    double worstDrift = 0.0;
    for (int k = 1; k < spec.frames; ++k) {
        for (int n = 0; n < spec.stepsPerFrame; ++n)
            flow.step(spec.timeBetweenFramesS / spec.stepsPerFrame);
        const auto [lo, hi] = std::minmax_element(flow.flux().values.begin(), flow.flux().values.end());
        ASSERT_GE(*lo, 0.0) << "frame " << k;
        ASSERT_LE(*hi, max0) << "frame " << k;
        const double drift = fluxPerLength(flow.flux()) - 1.0;
        std::printf("  frame %2d: flux per length 1 %+.4f, max %.4f (initial %.4f)\n", k, drift, *hi, max0);
        worstDrift = std::max(worstDrift, std::abs(drift));
    }
    EXPECT_LT(worstDrift, 0.03);
}

TEST(CurtainDetail, KelvinHelmholtzGrowsFromSmoothToStructured)
{
    const CurtainDetailSpec spec;
    CurtainFlow flow(spec);
    std::vector<double> energy, variance, tv;
    for (int k = 0; k < spec.frames; ++k) {
        if (k > 0)
            for (int n = 0; n < spec.stepsPerFrame; ++n)
                flow.step(spec.timeBetweenFramesS / spec.stepsPerFrame);
        energy.push_back(flow.crossStreamEnergy());
        variance.push_back(varianceAlongX(centreLine(flow.flux())));
        tv.push_back(totalVariationAlongX(flow.flux()));
        std::printf("  frame %2d: E_v %.3e km^4/s^2, var_x(y_c) %.3e km^2, TV_x %.3e /km\n", k, energy.back(), variance.back(),
                    tv.back());
    }
    // Linear growth: E_v rises frame after frame from frame 1 (the first interval sheds the
    // part of the seed that is not the growing mode) until the billows saturate.
    for (int k = 2; k <= 8; ++k)
        EXPECT_GT(energy[k], 2.0 * energy[k - 1]) << "frame " << k;
    EXPECT_GT(energy[8], 1000.0 * energy[1]);
    // Frame 0 has no structure along the curtain at all; the last frame has a lot.
    EXPECT_LT(variance[0], 1e-20);
    EXPECT_EQ(tv[0], 0.0);
    EXPECT_GT(variance.back(), 5.0 * variance[2]);
    EXPECT_GT(tv.back(), 5.0 * tv[2]);
    EXPECT_GT(variance.back(), 1.0); // the centre line wanders by more than a kilometre (rms)
}

TEST(CurtainDetail, EveryStepLeavesTheVelocityDivergenceFree)
{
    // Multigrid down to its tolerance, the FFT down to rounding.
    for (const auto& [solver, bound] : {std::pair{PressureSolver::Multigrid, 1e-6}, std::pair{PressureSolver::Fft, 1e-12}}) {
        CurtainDetailSpec spec;
        spec.nx = 256;
        spec.ny = 64;
        spec.pressureSolver = solver;
        CurtainFlow flow(spec);
        for (int n = 0; n < 40; ++n) {
            const std::optional<MultigridReport> report = flow.step(1.0);
            ASSERT_EQ(report.has_value(), solver == PressureSolver::Multigrid);
            if (report) {
                ASSERT_TRUE(report->converged) << "step " << n;
            }
            ASSERT_LE(divergenceRms(flow.velocity()), bound * gradientRms(flow.velocity())) << "step " << n;
        }
    }
}

TEST(CurtainDetail, TwoRunsGiveIdenticalBytes)
{
    const CurtainDetailSpec spec;
    const FluxFrames a = simulateCurtainDetail(spec);
    const FluxFrames b = simulateCurtainDetail(spec);
    ASSERT_EQ(a.flux.size(), std::size_t(spec.frames) * spec.nx * spec.ny);
    ASSERT_EQ(a.flux.size(), b.flux.size());
    EXPECT_EQ(std::memcmp(a.flux.data(), b.flux.data(), a.flux.size() * sizeof(float)), 0);
    CurtainDetailSpec other = spec;
    other.seed = 2;
    other.frames = 8;
    const FluxFrames c = simulateCurtainDetail(other);
    EXPECT_NE(std::memcmp(a.flux.data() + 7 * spec.nx * spec.ny, c.flux.data() + 7 * spec.nx * spec.ny,
                          std::size_t(spec.nx) * spec.ny * sizeof(float)),
              0);
}

FluxFrames smallFrames()
{
    CurtainDetailSpec spec;
    spec.nx = 128;
    spec.ny = 32;
    spec.stripLengthKm = 64.0;
    spec.stripWidthKm = 16.0;
    spec.frames = 5;
    spec.timeBetweenFramesS = 12.0;
    return simulateCurtainDetail(spec);
}

TEST(CurtainDetail, FramesLayoutAndNormalization)
{
    const FluxFrames f = smallFrames();
    EXPECT_EQ(f.nx, 128);
    EXPECT_EQ(f.ny, 32);
    EXPECT_EQ(f.frames, 5);
    EXPECT_EQ(f.texelKmX, 0.5f);
    EXPECT_EQ(f.texelKmY, 0.5f);
    for (int ix : {0, 77}) {
        double column = 0.0;
        for (int iy = 0; iy < f.ny; ++iy)
            column += f.at(0, ix, iy) * f.texelKmY;
        EXPECT_NEAR(column, 1.0, 1e-6);
    }
    // The curtain's centre line u = 0 lies between rows ny/2 − 1 and ny/2 (symmetric at frame 0).
    EXPECT_EQ(f.at(0, 5, f.ny / 2 - 1), f.at(0, 5, f.ny / 2));
    EXPECT_GT(f.at(0, 5, f.ny / 2), 10.0f * f.at(0, 5, f.ny / 2 + 4));
}

TEST(CurtainDetail, SamplerIsPeriodicAndHitsTexelsAndFrames)
{
    const FluxFrames f = smallFrames();
    const double lx = f.nx * double(f.texelKmX), ly = f.ny * double(f.texelKmY);
    for (double phase : {0.0, 0.37, 0.8, 1.0})
        for (double s : {0.1, 13.37, 63.9})
            for (double u : {-1.3, 0.0, 0.6, 7.9}) {
                const double value = sampleFlux(f, s, u, phase);
                EXPECT_NEAR(sampleFlux(f, s + lx, u, phase), value, 1e-12 * (1.0 + value));
                EXPECT_NEAR(sampleFlux(f, s - 3.0 * lx, u, phase), value, 1e-12 * (1.0 + value));
                EXPECT_NEAR(sampleFlux(f, s + 1000.0 * lx, u, phase), value, 1e-9 * (1.0 + value));
                EXPECT_NEAR(sampleFlux(f, s, u + ly, phase), value, 1e-12 * (1.0 + value));
            }
    // At a texel centre and a frame's phase the sampler returns the texel.
    for (int k = 0; k < f.frames; ++k) {
        const double phase = double(k) / (f.frames - 1);
        for (auto [ix, iy] : {std::pair{0, 0}, std::pair{17, 15}, std::pair{127, 31}}) {
            const double s = (ix + 0.5) * f.texelKmX, u = (iy + 0.5) * f.texelKmY - 0.5 * ly;
            EXPECT_NEAR(sampleFlux(f, s, u, phase), f.at(k, ix, iy), 1e-6 * f.at(k, ix, iy) + 1e-30);
        }
    }
    // Halfway between two frames, two texels along and two across (rows ny/2 − 1, ny/2 at u = 0).
    const int r = f.ny / 2;
    const double mid = sampleFlux(f, 11.0 * f.texelKmX, 0.0, 1.5 / (f.frames - 1));
    double expected = 0.0;
    for (int k : {1, 2})
        expected += 0.125 * (f.at(k, 10, r - 1) + f.at(k, 11, r - 1) + f.at(k, 10, r) + f.at(k, 11, r));
    EXPECT_NEAR(mid, expected, 1e-6 * expected);
    // Across the seam s = 0: halfway between the last and the first texel.
    const double seam = sampleFlux(f, 0.0, 0.0, 1.0);
    const int last = f.frames - 1;
    EXPECT_NEAR(seam, 0.25 * (f.at(last, 127, r - 1) + f.at(last, 0, r - 1) + f.at(last, 127, r) + f.at(last, 0, r)), 1e-6 * seam);
}

TEST(CurtainDetail, RejectsBadSpecs)
{
    CurtainDetailSpec spec;
    spec.nx = 500;
    EXPECT_THROW(CurtainFlow{spec}, std::invalid_argument);
    spec = CurtainDetailSpec{};
    spec.stripWidthKm = 128.0; // cells 0.25 km × 1 km
    EXPECT_THROW(CurtainFlow{spec}, std::invalid_argument);
    spec = CurtainDetailSpec{};
    spec.frames = 0;
    EXPECT_THROW(simulateCurtainDetail(spec), std::invalid_argument);
}

} // namespace
} // namespace aurorawall::components::fluid_detail::simulation
