#pragma once
// A strip of electrons along x in a strong uniform B along z, on a 2D periodic grid (x along the
// strip, y across) with the neutralising background spread over the whole box: the strip's E×B
// shear flow is diocotron unstable (R. H. Levy, Phys. Fluids 8, 1288 (1965)) and rolls up into
// vortices, the charge-sheet counterpart of Kelvin–Helmholtz. Used by the diocotron verify case and
// the plasma scene component.
#include "components/plasma/simulation/electrostatic_pic.h"
#include "components/plasma/simulation/particles.h"
#include "components/plasma/simulation/periodic_grid.h"

namespace aurorawall::components::plasma::simulation {

struct ElectronSheetSpec {
    int cellsAlong = 128;               // grid cells along x (the strip's period)
    int cellsAcross = 64;               // grid cells across y
    double lengthM = 128.0;             // box along x (m)
    double widthM = 64.0;               // box across y (m)
    double thicknessM = 16.0;           // the strip's full thickness 2a (m), centred at y = width/2
    double electronDensity = 2.43e8;    // n_b inside the strip (m⁻³)
    double magneticFieldT = 5e-5;       // B along z (T)
    double cyclotronFrequencyTimesDt = 5.0; // ω_c Δt
    int particlesPerCellPerAxis = 2;    // lattice spacing: this many per cell along each axis
    int mode = 1;                       // the seed's mode number along x
    double seedDisplacementM = 1e-7;    // δy = seed · sin(2π mode x/L) of every electron (m)
};

// The time step (s): ω_cΔt / ω_c.
double sheetTimeStep(const ElectronSheetSpec& spec);
// The diocotron frequency ω_D = e n_b/(ε₀ B) = ω_p²/ω_c (rad/s), the E×B shear inside the strip.
double diocotronFrequency(const ElectronSheetSpec& spec);

PeriodicGrid sheetGrid(const ElectronSheetSpec& spec);

// The strip as a cold lattice at rest: rows evenly spaced over its thickness, columns over the box's
// length, each electron displaced across by the seed. std::invalid_argument for a spec out of range.
Particles sheetElectrons(const ElectronSheetSpec& spec);

// The simulation of the spec: sheetElectrons on sheetGrid, B = (0, 0, B), Δt = sheetTimeStep.
ElectrostaticPic sheetSimulation(const ElectronSheetSpec& spec);

} // namespace aurorawall::components::plasma::simulation
