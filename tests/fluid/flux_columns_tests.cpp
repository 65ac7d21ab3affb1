// The running integrals across the flux frames (flux_columns.h, evaluated by the shader's
// fluxColumnValue) against direct quadrature of the renderer's bilinear lookup (fluid::sampleFlux).
#include "components/fluid_detail/simulation/flux_columns.h"

#include "common/glsl.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace aurorawall::f64 {
AURORAWALL_GLSL_PRECISION(double)
#include "components/aurora/flux_column.glsl"
} // namespace aurorawall::f64

using namespace aurorawall;
using namespace aurorawall::fluid;

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

// ∫ F(s, u') du' and ∫ u' F(s, u') du' from the strip's lower edge to u, by Simpson's rule on panels
// that end at every cell centre (F is linear between them, so the rule is exact).
glm::dvec2 integrateAcross(const FluxFrames& f, double s, double u, double phase)
{
    const double du = f.texelKmY, lower = -0.5 * f.ny * du;
    glm::dvec2 sum(0.0);
    double a = lower;
    while (a < u) {
        const double nextCentre = lower + (std::floor((a - lower) / du - 0.5 + 1e-9) + 1.5) * du;
        const double b = std::min(u, nextCentre);
        const double m = 0.5 * (a + b);
        const double fa = sampleFlux(f, s, a, phase), fm = sampleFlux(f, s, m, phase), fb = sampleFlux(f, s, b, phase);
        sum += (b - a) / 6.0 * glm::dvec2(fa + 4.0 * fm + fb, a * fa + 4.0 * m * fm + b * fb);
        a = b;
    }
    return sum;
}

// The shader's lookup in double, without the texture's filtering: the entry at the centre below u.
glm::dvec2 columnAt(const FluxColumns& c, const FluxFrames& f, int frame, int along, double u)
{
    const double du = f.texelKmY, halfWidth = 0.5 * f.ny * du;
    const double position = (u + halfWidth) / du - 0.5;
    const double below = std::clamp(std::floor(position), -1.0, double(c.rows - 2));
    const std::size_t at = 4 * ((std::size_t(below + 1.0) * c.frames + std::size_t(frame)) * c.nx + along);
    const glm::dvec4 texel(c.texels[at], c.texels[at + 1], c.texels[at + 2], c.texels[at + 3]);
    const double centre = (below + 0.5) * du - halfWidth;
    return f64::fluxColumnValue(texel, centre, u - centre, du);
}

} // namespace

TEST(FluxColumns, EqualTheIntegralsOfTheBilinearFluxAnywhereAcross)
{
    const FluxFrames f = randomFrames(6, 8, 3, 7);
    const FluxColumns c = fluxColumns(f);
    ASSERT_EQ(c.nx, 6);
    ASSERT_EQ(c.rows, 9);
    ASSERT_EQ(c.frames, 3);
    ASSERT_EQ(c.texels.size(), std::size_t(4 * 6 * 9 * 3));
    const double halfWidth = 0.5 * f.ny * f.texelKmY;
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> across(-halfWidth, halfWidth);
    for (int k = 0; k < f.frames; ++k)
        for (int i = 0; i < f.nx; ++i)
            for (int n = 0; n < 40; ++n) {
                // Column i sits at the cell centre along; frame k is phase k / (frames − 1).
                const double u = n == 0 ? -halfWidth : n == 1 ? halfWidth : across(rng);
                const glm::dvec2 exact = integrateAcross(f, (i + 0.5) * f.texelKmX, u, double(k) / (f.frames - 1));
                const glm::dvec2 table = columnAt(c, f, k, i, u);
                EXPECT_NEAR(table.x, exact.x, 2e-6 * (1.0 + std::abs(exact.x))) << k << " " << i << " " << u;
                EXPECT_NEAR(table.y, exact.y, 2e-6 * (1.0 + std::abs(exact.y))) << k << " " << i << " " << u;
            }
}

// Over a short interval the column's mass is the flux there times its width: the table has the
// flux's own resolution, not a cell average's.
TEST(FluxColumns, ShortIntervalsSeeTheLocalFlux)
{
    const FluxFrames f = randomFrames(4, 16, 2, 11);
    const FluxColumns c = fluxColumns(f);
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> across(-1.9, 1.9);
    for (int n = 0; n < 200; ++n) {
        const double u = across(rng), h = 1e-4;
        const double mass = columnAt(c, f, 1, 2, u + h).x - columnAt(c, f, 1, 2, u).x;
        EXPECT_NEAR(mass / h, sampleFlux(f, 2.5 * f.texelKmX, u + 0.5 * h, 1.0), 2e-3) << u;
    }
}
