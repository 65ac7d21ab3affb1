#include "components/fluid_detail/simulation/flux_columns.h"

#include "common/glsl.h"

#include <algorithm>

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

FluxRows fluxRows(const FluxFrames& f)
{
    FluxRows r;
    r.ny = f.ny;
    r.entries = f.nx + 1;
    r.frames = f.frames;
    r.texels.assign(std::size_t(4) * r.ny * r.entries * r.frames, 0.0f);
    std::vector<double> row(f.nx);
    for (int k = 0; k < f.frames; ++k)
        for (int j = 0; j < f.ny; ++j) {
            for (int i = 0; i < f.nx; ++i)
                row[i] = f.at(k, i, j);
            runningIntegrals(row, f.texelKmX, 0.0, &r.texels[4 * (std::size_t(k) * r.ny + j)],
                             4 * std::size_t(r.ny) * r.frames);
        }
    return r;
}

FluxTables packFluxTables(const FluxColumns& columns, const FluxRows& rows)
{
    FluxTables t;
    t.nx = columns.nx;
    t.ny = rows.ny;
    t.frames = columns.frames;
    t.width = std::max(t.nx, t.ny) + 2;
    t.columnTiles = t.width / (t.nx + 2);
    t.rowTiles = t.width / (t.ny + 2);
    t.firstRowLayer = (columns.rows + t.columnTiles - 1) / t.columnTiles;
    t.layers = t.firstRowLayer + (rows.entries + t.rowTiles - 1) / t.rowTiles;
    t.texels.assign(std::size_t(4) * t.width * t.frames * t.layers, 0.0f);
    // Entry e of a table whose entries hold n cells (source texel of cell i, frame k: from(e, k, i)).
    const auto place = [&](int entries, int n, int tiles, int firstLayer, auto from) {
        for (int e = 0; e < entries; ++e)
            for (int k = 0; k < t.frames; ++k) {
                const int layer = firstLayer + e / tiles, x0 = (e % tiles) * (n + 2);
                float* out = &t.texels[4 * ((std::size_t(layer) * t.frames + k) * t.width + x0)];
                for (int x = 0; x < n + 2; ++x) {
                    const float* in = from(e, k, (x - 1 + n) % n);
                    std::copy(in, in + 4, out + 4 * x);
                }
            }
    };
    place(columns.rows, t.nx, t.columnTiles, 0, [&](int r, int k, int i) {
        return &columns.texels[4 * ((std::size_t(r) * columns.frames + k) * columns.nx + i)];
    });
    place(rows.entries, t.ny, t.rowTiles, t.firstRowLayer, [&](int e, int k, int j) {
        return &rows.texels[4 * ((std::size_t(e) * rows.frames + k) * rows.ny + j)];
    });
    return t;
}

} // namespace aurorawall::fluid
