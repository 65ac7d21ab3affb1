#pragma once
// The flux frames' running integrals across the strip, so that the renderer integrates a ray step
// across a thin curtain in closed form instead of point-sampling it (docs/aurora-physics.md, "Integrating
// across the curtain"). The flux F(s, u), as the renderer's texture lookup gives it
// (sampleFlux: linear between cell centres, periodic), has the running integrals across it
//   C(u) = ∫_{−Ly/2}^{u} F du',   M(u) = ∫_{−Ly/2}^{u} u' F du'
// (the mass below u and its first moment). Between two cell centres F is linear, so C and M are
// polynomials there, given exactly by shaders/components/aurora/flux_column.glsl (fluxColumnValue)
// from the entry at the lower centre: (C(c), M(c), F(c), F(c + Δ) − F(c)). The entries sit at the
// centres c_j = (j + ½)Δu − Ly/2 for j = −1 … ny − 1 (the first lies half a cell below the strip,
// where the periodic flux still rises toward its first centre), for every cell centre along and
// every frame.
#include "components/roles/flux_frames.h"

#include <vector>

namespace aurorawall::components::roles {

// A table of running integrals over one axis of the strip (q), at every cell centre of the other axis
// (p) and every frame: entries at the centres of q's cells, from half a cell before the strip's start.
struct FluxIntegrals {
    int cells = 0;   // cells along p, as the frames
    int entries = 0; // cells along q + 1: entry e holds centre e − 1
    int frames = 0;
    // (integral, first moment, F, ΔF) in 1, km, 1/km, 1/km: texels[4·((e·frames + k)·cells + p) + {0, 1, 2, 3}]
    // (an entry is a layer of a 2D array texture whose x runs along p and y through the frames).
    std::vector<float> texels;
};

// Across (q = u, p along: C and M above; entries at c_j for j = −1 … ny − 1, cells = nx).
FluxIntegrals fluxColumns(const FluxFrames& frames);

// The same running integrals along the strip, for a ray step that runs along a curtain: at each cell
// centre across, A(s) = ∫_0^s F ds' and B(s) = ∫_0^s s' F ds' (s along from the strip's start), from the
// entry at the centre below s: (A(c), B(c), F(c), F(c + Δ) − F(c)), evaluated by the same fluxColumnValue.
// The entries sit at the centres c_i = (i + ½)Δs for i = −1 … nx − 1 (the first half a cell before the
// strip's start, where the periodic flux still rises toward its first centre); cells = ny. Across, the
// texture interpolates A, B and F linearly between cell centres (periodic), which is exactly the integral
// along of the flux as the renderer interpolates it there.
FluxIntegrals fluxRows(const FluxFrames& frames);

// Both tables in one 2D array texture, so that a shader reads either through one sampler and one code path
// (a GPU runs both sides of a branch that differs between neighbouring pixels). Each entry (a column's
// entry across, or a row's entry along) is a strip of its cells with a ghost texel at either end holding
// the periodic neighbour (the last cell before the first, the first after the last), so GL_LINEAR with
// clamp-to-edge interpolates periodically; as many strips as fit side by side share a layer.
//   width = max(nx, ny) + 2, height = frames;
//   column entry r (0 … ny): layer r / columnTiles, texels from x = (r mod columnTiles)·(nx + 2);
//   row entry e (0 … nx):    layer firstRowLayer + e / rowTiles, texels from x = (e mod rowTiles)·(ny + 2);
//   texel x0 + 1 + i holds cell i, x0 the cell n − 1, x0 + n + 1 the cell 0 (n = nx or ny).
struct FluxTables {
    int nx = 0, ny = 0, frames = 0;
    int width = 0, layers = 0;
    int columnTiles = 0, rowTiles = 0, firstRowLayer = 0;
    std::vector<float> texels; // RGBA: texels[4·((layer·frames + k)·width + x)]
};

FluxTables packFluxTables(const FluxIntegrals& columns, const FluxIntegrals& rows);

} // namespace aurorawall::components::roles
