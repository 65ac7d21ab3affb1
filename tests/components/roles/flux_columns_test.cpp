// The running integrals across the flux frames (flux_columns.h, evaluated by the shader's
// fluxColumnValue) against direct quadrature of the renderer's bilinear lookup (roles::sampleFlux).
#include "components/roles/flux_columns.h"

#include "common/glsl.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <utility>

namespace aurorawall::f64 {
namespace {
AURORAWALL_GLSL_PRECISION(double)
#include "components/aurora/flux_column.glsl"
} // namespace
} // namespace aurorawall::f64

using namespace aurorawall;
using namespace aurorawall::components::roles;

namespace {

// Small frames with random flux: no structure the table could be tuned to.
FluxFrames randomFrames(int nx, int ny, int frames, unsigned seed)
{
    FluxFrames f;
    f.nx = nx;
    f.ny = ny;
    f.frames = frames;
    f.texelKmX = 0.5f;
    f.texelKmY = 0.25f;
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> value(0.0f, 2.0f);
    for (int i = 0; i < nx * ny * frames; ++i)
        f.flux.push_back(value(rng));
    return f;
}

// ∫ F dq and ∫ q F dq over q (across: q = u from the strip's lower edge; along: q = s from the strip's
// start, beyond it periodic) up to `to`, at the fixed other coordinate, by Simpson's rule on panels that
// end at every cell centre (F is linear between them, so the rule is exact).
glm::dvec2 integrateLine(const FluxFrames& f, bool along, double fixed, double to, double phase)
{
    const double delta = along ? f.texelKmX : f.texelKmY, origin = along ? 0.0 : -0.5 * f.ny * f.texelKmY;
    const auto flux = [&](double q) { return along ? sampleFlux(f, q, fixed, phase) : sampleFlux(f, fixed, q, phase); };
    glm::dvec2 sum(0.0);
    double a = origin;
    while (a < to) {
        const double nextCentre = origin + (std::floor((a - origin) / delta - 0.5 + 1e-9) + 1.5) * delta;
        const double b = std::min(to, nextCentre);
        const double m = 0.5 * (a + b);
        const double fa = flux(a), fm = flux(m), fb = flux(b);
        sum += (b - a) / 6.0 * glm::dvec2(fa + 4.0 * fm + fb, a * fa + 4.0 * m * fm + b * fb);
        a = b;
    }
    return sum;
}

// The shader's lookup in double, without the texture's filtering: the entry of table t at the centre below
// q, at cell p of the other axis.
glm::dvec2 tableAt(const FluxIntegrals& t, const FluxFrames& f, bool along, int frame, int p, double q)
{
    const double delta = along ? f.texelKmX : f.texelKmY, origin = along ? 0.0 : -0.5 * f.ny * f.texelKmY;
    const double below = std::clamp(std::floor((q - origin) / delta - 0.5), -1.0, double(t.entries - 2));
    const std::size_t at = 4 * ((std::size_t(below + 1.0) * t.frames + std::size_t(frame)) * t.cells + p);
    const glm::dvec4 texel(t.texels[at], t.texels[at + 1], t.texels[at + 2], t.texels[at + 3]);
    const double centre = origin + (below + 0.5) * delta;
    return f64::fluxColumnValue(texel, centre, q - centre, delta);
}

// The table over q (across, or along when `along`) against integrateLine at every cell centre p of the
// other axis, every frame and 40 places q between the strip's ends (both ends included).
void expectTheQuadratureEverywhere(const FluxFrames& f, const FluxIntegrals& t, bool along, unsigned seed)
{
    const double halfWidth = 0.5 * f.ny * f.texelKmY;
    const double lo = along ? 0.0 : -halfWidth, hi = along ? f.nx * f.texelKmX : halfWidth;
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> place(lo, hi);
    for (int k = 0; k < f.frames; ++k)
        for (int p = 0; p < t.cells; ++p)
            for (int n = 0; n < 40; ++n) {
                // Cell p's centre on the other axis; frame k is phase k / (frames − 1).
                const double q = n == 0 ? lo : n == 1 ? hi : place(rng);
                const double fixed = along ? (p + 0.5) * f.texelKmY - halfWidth : (p + 0.5) * f.texelKmX;
                const glm::dvec2 exact = integrateLine(f, along, fixed, q, double(k) / (f.frames - 1));
                const glm::dvec2 table = tableAt(t, f, along, k, p, q);
                EXPECT_NEAR(table.x, exact.x, 2e-6 * (1.0 + std::abs(exact.x))) << k << " " << p << " " << q;
                EXPECT_NEAR(table.y, exact.y, 2e-6 * (1.0 + std::abs(exact.y))) << k << " " << p << " " << q;
            }
}

// Table t holds `cells` lines of `entries` entries in each of `frames` frames, 4 floats each.
void expectTheShape(const FluxIntegrals& t, int cells, int entries, int frames)
{
    ASSERT_EQ(t.cells, cells);
    ASSERT_EQ(t.entries, entries);
    ASSERT_EQ(t.frames, frames);
    ASSERT_EQ(t.texels.size(), std::size_t(4 * cells * entries * frames));
}

// Over a short interval at 200 places q from `lo` to `hi` along cell 2's centre line, in frame 1 (phase 1),
// the line's mass is the flux there times the interval's length: the table has the flux's own
// resolution, not a cell average's.
void expectTheLocalFlux(const FluxFrames& f, const FluxIntegrals& t, bool along, double lo, double hi, unsigned seed)
{
    const double fixed = along ? 2.5 * f.texelKmY - 0.5 * f.ny * f.texelKmY : 2.5 * f.texelKmX;
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> place(lo, hi);
    for (int n = 0; n < 200; ++n) {
        const double q = place(rng), h = 1e-4;
        const double mass = tableAt(t, f, along, 1, 2, q + h).x - tableAt(t, f, along, 1, 2, q).x;
        const double flux = along ? sampleFlux(f, q + 0.5 * h, fixed, 1.0) : sampleFlux(f, fixed, q + 0.5 * h, 1.0);
        EXPECT_NEAR(mass / h, flux, 2e-3) << q;
    }
}

} // namespace

TEST(FluxColumns, EqualTheIntegralsOfTheBilinearFluxAnywhereAcross)
{
    const FluxFrames f = randomFrames(6, 8, 3, 7);
    const FluxIntegrals c = fluxColumns(f);
    ASSERT_NO_FATAL_FAILURE(expectTheShape(c, 6, 9, 3));
    expectTheQuadratureEverywhere(f, c, false, 3);
}

// Over a short interval the column's mass is the flux there times its width.
TEST(FluxColumns, ShortIntervalsSeeTheLocalFlux)
{
    const FluxFrames f = randomFrames(4, 16, 2, 11);
    expectTheLocalFlux(f, fluxColumns(f), false, -1.9, 1.9, 5);
}

TEST(FluxRows, EqualTheIntegralsOfTheBilinearFluxAnywhereAlong)
{
    const FluxFrames f = randomFrames(7, 5, 3, 13);
    const FluxIntegrals r = fluxRows(f);
    ASSERT_NO_FATAL_FAILURE(expectTheShape(r, 5, 8, 3));
    expectTheQuadratureEverywhere(f, r, true, 17);
}

// Over a short interval the row's mass is the flux there times its length.
TEST(FluxRows, ShortIntervalsSeeTheLocalFlux)
{
    const FluxFrames f = randomFrames(16, 4, 2, 19);
    expectTheLocalFlux(f, fluxRows(f), true, 0.0, f.nx * f.texelKmX - 1e-3, 23);
}

// The packed texture holds every entry of both tables at its documented place, with the periodic
// neighbours as ghosts at either end, whichever axis is longer.
TEST(FluxTables, HoldEveryEntryOfBothTablesWithPeriodicGhosts)
{
    for (auto [nx, ny] : {std::pair{20, 4}, std::pair{3, 11}, std::pair{6, 6}}) {
        const FluxFrames f = randomFrames(nx, ny, 2, 29);
        const FluxIntegrals columns = fluxColumns(f);
        const FluxIntegrals rows = fluxRows(f);
        const FluxTables t = packFluxTables(columns, rows);
        ASSERT_EQ(t.width, std::max(nx, ny) + 2);
        ASSERT_EQ(t.texels.size(), std::size_t(4) * t.width * t.frames * t.layers);
        const auto texel = [&](int layer, int k, int x, int channel) {
            return t.texels[4 * ((std::size_t(layer) * t.frames + k) * t.width + x) + channel];
        };
        for (int k = 0; k < f.frames; ++k)
            for (int channel = 0; channel < 4; ++channel) {
                for (int r = 0; r < columns.entries; ++r) {
                    const int layer = r / t.columnTiles, x0 = (r % t.columnTiles) * (nx + 2);
                    for (int x = 0; x < nx + 2; ++x) {
                        const int i = (x - 1 + nx) % nx;
                        EXPECT_EQ(texel(layer, k, x0 + x, channel),
                                  columns.texels[4 * ((std::size_t(r) * f.frames + k) * nx + i) + channel]);
                    }
                }
                for (int e = 0; e < rows.entries; ++e) {
                    const int layer = t.firstRowLayer + e / t.rowTiles, x0 = (e % t.rowTiles) * (ny + 2);
                    ASSERT_LT(layer, t.layers);
                    for (int x = 0; x < ny + 2; ++x) {
                        const int j = (x - 1 + ny) % ny;
                        EXPECT_EQ(texel(layer, k, x0 + x, channel),
                                  rows.texels[4 * ((std::size_t(e) * f.frames + k) * ny + j) + channel]);
                    }
                }
            }
        EXPECT_GE(t.firstRowLayer * t.columnTiles, columns.entries);
    }
}
