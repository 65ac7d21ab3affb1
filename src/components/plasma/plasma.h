#pragma once
// The plasma component: curtain detail from the particle-in-cell plasma. A diocotron-unstable strip of
// electrons along the curtain, in the geomagnetic field along the field line, rolls up into vortices
// (the curls of auroral arcs: Hallinan & Davis, Planet. Space Sci. 18, 1735 (1970)); simulated once at
// start-up (sheet_frames.h), its electron density frames replace fluid_detail's in the aurora's
// curtain profile. docs/PLASMA.md, "Driving the aurora".
#include "components/plasma/sheet_frames.h"
#include "scene/component.h"

namespace aurorawall::components::plasma {

struct Settings : scene::SettingsOf<Settings> {
    static constexpr const char* kComponent = "plasma";
    int cellsAlong = 512;
    int cellsAcross = 128;
    double stripLengthKm = 128.0;
    double stripWidthKm = 32.0;
    double sheetThicknessKm = 2.0;
    double electronDensityM3 = 1e7;  // n_b in the strip
    double magneticFieldT = 1e-5;    // B along the field line
    double timeStepS = 2.5e-6;
    int particlesPerCellAxis = 2;
    int seedMode = 8;                // vortices along the strip
    double seedAmplitudeKm = 0.02;   // the strip's initial sinusoidal displacement across
    int frames = 16;
    double timeBetweenFramesS = 1.4e-4;
};

const scene::Component& component();

// The simulation of a scene's [plasma] table (lengths to metres, steps between frames rounded).
SheetFramesSpec sheetFramesSpec(const Settings& plasma);

} // namespace aurorawall::components::plasma
