#include "components/fluid_detail/simulation/flux_columns.h"

#include "common/glsl.h"

namespace aurorawall::f64 {
namespace {
AURORAWALL_GLSL_PRECISION(double)
#include "components/aurora/flux_column.glsl"
} // namespace
} // namespace aurorawall::f64

namespace aurorawall::fluid {

namespace {

// The entries (C, M, F, ΔF) at the centres origin + (i + ½)Δ, i = −1 … n − 1, of the periodic flux
// `values` (n cell centres), written to out[stride·(i + 1)]; C and M are 0 at origin.
void runningIntegrals(const std::vector<double>& values, double delta, double origin, float* out, std::size_t stride)
{
    const int n = static_cast<int>(values.size());
    const auto flux = [&](int i) { return values[((i % n) + n) % n]; };
    const double first = origin - 0.5 * delta;
    const glm::dvec2 toOrigin =
        f64::fluxColumnValue(glm::dvec4(0.0, 0.0, flux(-1), flux(0) - flux(-1)), first, 0.5 * delta, delta);
    glm::dvec2 integrals = -toOrigin;
    for (int r = 0; r <= n; ++r) {
        const int i = r - 1;
        const glm::dvec4 entry(integrals.x, integrals.y, flux(i), flux(i + 1) - flux(i));
        for (int channel = 0; channel < 4; ++channel)
            out[stride * std::size_t(r) + std::size_t(channel)] = static_cast<float>(entry[channel]);
        integrals = f64::fluxColumnValue(entry, first + r * delta, delta, delta);
    }
}

} // namespace

FluxColumns fluxColumns(const FluxFrames& f)
{
    FluxColumns c;
    c.nx = f.nx;
    c.rows = f.ny + 1;
    c.frames = f.frames;
    c.texels.assign(std::size_t(4) * c.nx * c.rows * c.frames, 0.0f);
    std::vector<double> column(f.ny);
    for (int k = 0; k < f.frames; ++k)
        for (int i = 0; i < f.nx; ++i) {
            for (int j = 0; j < f.ny; ++j)
                column[j] = f.at(k, i, j);
            runningIntegrals(column, f.texelKmY, -0.5 * f.ny * double(f.texelKmY),
                             &c.texels[4 * (std::size_t(k) * c.nx + i)], 4 * std::size_t(c.nx) * c.frames);
        }
    return c;
}

} // namespace aurorawall::fluid
