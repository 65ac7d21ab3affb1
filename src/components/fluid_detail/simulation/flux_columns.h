#pragma once
// The flux frames' running integrals across the strip, so that the renderer integrates a ray step
// across a thin curtain in closed form instead of point-sampling it (docs/aurora.md, "Integrating
// across the curtain"). The flux F(s, u), as the renderer's texture lookup gives it
// (fluid::sampleFlux: linear between cell centres, periodic), has the running integrals across it
//   C(u) = ∫_{−Ly/2}^{u} F du',   M(u) = ∫_{−Ly/2}^{u} u' F du'
// (the mass below u and its first moment). Between two cell centres F is linear, so C and M are
// polynomials there, given exactly by shaders/components/aurora/flux_column.glsl (fluxColumnValue)
// from the entry at the lower centre: (C(c), M(c), F(c), F(c + Δ) − F(c)). The entries sit at the
// centres c_j = (j + ½)Δu − Ly/2 for j = −1 … ny − 1 (the first lies half a cell below the strip,
// where the periodic flux still rises toward its first centre), for every cell centre along and
// every frame.
#include "components/fluid_detail/simulation/curtain_detail.h"

#include <vector>

namespace aurorawall::fluid {

struct FluxColumns {
    int nx = 0;      // cells along, as the frames
    int rows = 0;    // ny + 1 entries across: row r holds centre j = r − 1
    int frames = 0;
    // (C, M, F, ΔF) in 1, km, 1/km, 1/km: texels[4·((r·frames + k)·nx + i) + {0, 1, 2, 3}] (a row
    // across is a layer of a 2D array texture whose x runs along and y through the frames).
    std::vector<float> texels;
};

FluxColumns fluxColumns(const FluxFrames& frames);

} // namespace aurorawall::fluid
