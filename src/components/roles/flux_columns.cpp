#include "components/roles/flux_columns.h"

#include "common/glsl.h"

#include <algorithm>

namespace aurorawall::components::roles::f64 {
namespace {
AURORAWALL_GLSL_PRECISION(double)
#include "components/aurora/flux_column.glsl"
} // namespace
} // namespace aurorawall::components::roles::f64

namespace aurorawall::components::roles {

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

namespace {

// The running integrals over q (across when along is false, else along) of every line of cells along q,
// at every cell of p and every frame.
FluxIntegrals fluxIntegrals(const FluxFrames& f, bool along)
{
    FluxIntegrals t;
    t.cells = along ? f.ny : f.nx;
    const int cellsQ = along ? f.nx : f.ny;
    t.entries = cellsQ + 1;
    t.frames = f.frames;
    t.texels.assign(std::size_t(4) * t.cells * t.entries * t.frames, 0.0f);
    const double delta = along ? f.texelKmX : f.texelKmY;
    const double origin = along ? 0.0 : -0.5 * f.ny * double(f.texelKmY);
    std::vector<double> line(cellsQ);
    for (int k = 0; k < f.frames; ++k)
        for (int p = 0; p < t.cells; ++p) {
            for (int q = 0; q < cellsQ; ++q)
                line[q] = along ? f.at(k, q, p) : f.at(k, p, q);
            runningIntegrals(line, delta, origin, &t.texels[4 * (std::size_t(k) * t.cells + p)],
                             4 * std::size_t(t.cells) * t.frames);
        }
    return t;
}

} // namespace

FluxIntegrals fluxColumns(const FluxFrames& f)
{
    return fluxIntegrals(f, false);
}

FluxIntegrals fluxRows(const FluxFrames& f)
{
    return fluxIntegrals(f, true);
}

FluxTables packFluxTables(const FluxIntegrals& columns, const FluxIntegrals& rows)
{
    FluxTables t;
    t.nx = columns.cells;
    t.ny = rows.cells;
    t.frames = columns.frames;
    t.width = std::max(t.nx, t.ny) + 2;
    t.columnTiles = t.width / (t.nx + 2);
    t.rowTiles = t.width / (t.ny + 2);
    t.firstRowLayer = (columns.entries + t.columnTiles - 1) / t.columnTiles;
    t.layers = t.firstRowLayer + (rows.entries + t.rowTiles - 1) / t.rowTiles;
    t.texels.assign(std::size_t(4) * t.width * t.frames * t.layers, 0.0f);
    // Every entry of a table as a strip of its cells between the periodic ghosts, `tiles` strips a layer.
    const auto place = [&](const FluxIntegrals& table, int tiles, int firstLayer) {
        const int n = table.cells;
        for (int e = 0; e < table.entries; ++e)
            for (int k = 0; k < t.frames; ++k) {
                const int layer = firstLayer + e / tiles, x0 = (e % tiles) * (n + 2);
                float* out = &t.texels[4 * ((std::size_t(layer) * t.frames + k) * t.width + x0)];
                for (int x = 0; x < n + 2; ++x) {
                    const float* in = &table.texels[4 * ((std::size_t(e) * t.frames + k) * n + (x - 1 + n) % n)];
                    std::copy(in, in + 4, out + 4 * x);
                }
            }
    };
    place(columns, t.columnTiles, 0);
    place(rows, t.rowTiles, t.firstRowLayer);
    return t;
}

} // namespace aurorawall::components::roles
