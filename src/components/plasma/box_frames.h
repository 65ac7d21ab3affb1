#pragma once
// The plasma box's frames: a 3D periodic box of electrons on a neutralising ion background in a
// uniform magnetic field along z (the field line), loaded as two cold beams streaming along ±z at
// the speed that makes the seeded mode the fastest-growing of the two-stream instability. The seed
// displaces every electron along z by a sin(k z + φ(x, y)), its phase φ varying across the field, so
// the bunches that grow in each flux tube lie on curved sheets. CPU, serial, double, deterministic:
// every rank computes the same bytes, or reads them from the table cache.
#include "components/plasma/simulation/particles.h"
#include "components/plasma/simulation/periodic_grid.h"

#include <string>
#include <vector>

namespace aurorawall::components::plasma {

struct BoxFramesSpec {
    int cells = 32;                 // per axis
    double sideM = 8000.0;          // the cube's side
    double electronDensity = 1e7;   // n₀, m⁻³
    double magneticFieldT = 5e-5;   // along z
    double timeStepS = 1.1e-6;
    int particlesPerCellAxis = 1;   // per beam: this cubed in every cell
    int seedMode = 4;               // wavelengths along z
    double seedAmplitudeM = 4.0;    // a
    int frames = 24;                // frame 0 is the seeded start
    int stepsPerFrame = 10;
};

// Symmetric cold beams of n₀/2 each at ±v₀ grow fastest at k v₀ = √(3/8) ω_p, at the rate
// ω_p/(2√2) (from the dispersion relation 1 = (ω_p²/2)[(ω − kv₀)⁻² + (ω + kv₀)⁻²] of the
// two-stream instability; F. F. Chen, Introduction to Plasma Physics and Controlled Fusion, 3rd ed.,
// 2016): v₀ (m/s) for k the seeded mode's wavenumber.
double boxBeamSpeed(const BoxFramesSpec& spec);

// The box's grid: cells³ cells of side sideM / cells.
simulation::PeriodicGrid boxGrid(const BoxFramesSpec& spec);

// Two cold beams on the same lattice (perCellAxis³ electrons per cell each), displaced along z by
// a sin(k z + φ(x, y)) with φ = π sin(2πx/L) sin(2πy/L), at +v₀ and −v₀ along z.
simulation::Particles boxElectrons(const BoxFramesSpec& spec);

// A frame: n/n₀ at the cell centres, the CIC deposit of the electrons moved back by half a cell on
// every axis, plus the mean the deposit removed; x fastest, then y, z.
std::vector<float> boxFrameDensity(const BoxFramesSpec& spec, const simulation::PeriodicGrid& grid,
                                   const simulation::Particles& electrons);

struct BoxFrames {
    int cells = 0;
    int frames = 0;
    // n/n₀ at the cell centres ((i + ½)Δ, (j + ½)Δ, (k + ½)Δ); x fastest, then y, z, frame.
    std::vector<float> density;
};

BoxFrames simulateBoxFrames(const BoxFramesSpec& spec);

// "plasma box frames v1", every spec field (doubles in hexadecimal, exact) and the executable's digest.
std::string boxFramesCacheKey(const BoxFramesSpec& spec);

struct CachedBoxFrames {
    BoxFrames frames;
    std::string outcome; // io::CachedTable::outcome
};

// simulateBoxFrames(spec), read from `cacheDirectory` when a good file is there, else simulated and
// written there (an empty directory: simulated, not cached). Bit-identical either way.
CachedBoxFrames cachedBoxFrames(const BoxFramesSpec& spec, const std::string& cacheDirectory);

} // namespace aurorawall::components::plasma
