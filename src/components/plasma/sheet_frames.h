#pragma once
// The plasma component's curtain detail: frames of the electron density of a diocotron-unstable
// electron strip (simulation/electron_sheet.h) as it rolls up into vortices, in the form the aurora's
// curtain profile samples (roles::FluxFrames: x along the curtain, y across, frame by frame). CPU,
// serial and deterministic: every rank computes the same bytes, or reads them from the table cache.
#include "components/roles/curtain_detail.h"
#include "components/plasma/simulation/electron_sheet.h"

#include <string>

namespace aurorawall::components::plasma {

struct SheetFramesSpec {
    simulation::ElectronSheetSpec sheet; // lengths in metres
    int frames = 16;                             // frame 0 is the initial strip
    int stepsPerFrame = 80;                      // time steps between frames
};

// Frame k is the electron density after k·stepsPerFrame steps, at the texel centres
// ((i + ½)Δx, (j + ½)Δy) of the grid's cells, divided by n_b times the strip's thickness in km: so
// ∫F du = 1 (1/km, u in km) for every column of frame 0, as the fluid's frames.
roles::FluxFrames simulateSheetFrames(const SheetFramesSpec& spec);

// One such frame from the electrons on the spec's grid (simulation::sheetGrid).
std::vector<float> sheetFrameDensity(const SheetFramesSpec& spec, const simulation::PeriodicGrid& grid,
                                     const simulation::Particles& electrons);

// Frame 0's shape for the aurora's curtain model: its measured standard deviation across, its reach,
// the strip's length, and 1/(frame 0's largest value), which makes the smooth strip's peak 1.
roles::DetailShape sheetDetailShape(const SheetFramesSpec& spec, const roles::FluxFrames& frames);

struct CachedSheetFrames {
    roles::FluxFrames frames;
    std::string outcome; // io::CachedTable::outcome
};

// The cache key: "plasma sheet frames v1", every spec field (doubles in hexadecimal, exact) and the
// executable's digest.
std::string sheetFramesCacheKey(const SheetFramesSpec& spec);

// simulateSheetFrames(spec), read from `cacheDirectory` when a good file is there, else simulated and
// written there (an empty directory: simulated, not cached). Bit-identical either way.
CachedSheetFrames cachedSheetFrames(const SheetFramesSpec& spec, const std::string& cacheDirectory);

} // namespace aurorawall::components::plasma
