#include "components/fluid_detail/simulation/flux_columns.h"

#include "common/glsl.h"

namespace aurorawall::f64 {
namespace {
AURORAWALL_GLSL_PRECISION(double)
#include "components/aurora/curtain_column.glsl"
} // namespace
} // namespace aurorawall::f64

namespace aurorawall::fluid {

FluxColumns fluxColumns(const FluxFrames& f)
{
    FluxColumns c;
    c.nx = f.nx;
    c.rows = f.ny + 1;
    c.frames = f.frames;
    c.texels.assign(std::size_t(4) * c.nx * c.rows * c.frames, 0.0f);
    const double du = f.texelKmY;
    const double halfWidth = 0.5 * f.ny * du;
    for (int k = 0; k < f.frames; ++k)
        for (int i = 0; i < f.nx; ++i) {
            // Row 0: centre −1 (the last row's flux, periodic), its integrals chosen so that C and M
            // are 0 at the strip's lower edge, half a cell above it.
            const double below = f.at(k, i, f.ny - 1);
            const double first = -halfWidth - 0.5 * du;
            const glm::dvec2 toEdge = f64::fluxColumnValue(glm::dvec4(0.0, 0.0, below, f.at(k, i, 0) - below), first,
                                                           0.5 * du, du);
            glm::dvec4 entry(-toEdge.x, -toEdge.y, below, f.at(k, i, 0) - below);
            for (int r = 0; r < c.rows; ++r) {
                const double centre = first + r * du;
                if (r > 0) {
                    const double flux = f.at(k, i, r - 1);
                    const double next = f.at(k, i, r % f.ny);
                    entry = glm::dvec4(entry.x, entry.y, flux, next - flux);
                }
                const std::size_t at = 4 * ((std::size_t(k) * c.rows + r) * c.nx + i);
                for (int channel = 0; channel < 4; ++channel)
                    c.texels[at + channel] = static_cast<float>(entry[channel]);
                // The integrals at the next centre.
                const glm::dvec2 next = f64::fluxColumnValue(entry, centre, du, du);
                entry.x = next.x;
                entry.y = next.y;
            }
        }
    return c;
}

} // namespace aurorawall::fluid
