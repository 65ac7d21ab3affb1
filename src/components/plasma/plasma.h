#pragma once
// The plasma component: curtain detail from the particle-in-cell plasma. A diocotron-unstable strip of
// electrons along the curtain, in the geomagnetic field along the field line, rolls up into vortices
// (the curls of auroral arcs: Hallinan & Davis, Planet. Space Sci. 18, 1735 (1970)); simulated once at
// start-up (sheet_frames.h) or live on the GPU (device = "gpu"), its electron density replaces
// fluid_detail's in the aurora's curtain profile. docs/PLASMA.md, "Driving the aurora".
// With kind = "box" it also simulates a 3D box of plasma along the field lines (box_frames.h) and
// raymarches its electron density as the green line's emission. docs/PLASMA.md, "The plasma box".
// The step a time shows, for both devices: see curlsStep and boxStep.
#include "components/plasma/box_frames.h"
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

    // cpu: the frames simulated at start-up in double (sheet_frames.h, box_frames.h); gpu: the same
    // simulations run live in compute shaders (live_pic.h), stepped to the master's clock.
    enum class Device { Cpu, Gpu };
    Device device = Device::Cpu;

    enum class Kind { Curls, Box };
    Kind kind = Kind::Curls;
    // kind = "box": the box's simulation (box_frames.h), place (its centre; z radial, x east, y north)
    // and glow. The frames play over boxPlayS seconds of the clock, then again from the start.
    int boxCells = 32;
    double boxSideKm = 8.0;
    double boxElectronDensityM3 = 1e7;
    double boxMagneticFieldT = 5e-5;
    double boxTimeStepS = 1.1e-6;
    int boxParticlesPerCellAxis = 1;
    int boxSeedMode = 4;
    double boxSeedAmplitudeKm = 0.004;
    int boxFrames = 24;
    double boxTimeBetweenFramesS = 1.1e-5;
    double boxLatitudeDeg = 66.7;
    double boxLongitudeDeg = 22.0;
    double boxAltitudeKm = 110.0;
    double boxPlayS = 12.0;
    double boxRayleighPerKm = 500.0; // the 557.7 nm column brightness per km of path at n = n₀
    int boxStepsPerCell = 2;         // the march's midpoint steps per cell side along a ray's chord
};

const scene::Component& component();

// The simulation of a scene's [plasma] table (lengths to metres, steps between frames rounded).
SheetFramesSpec sheetFramesSpec(const Settings& plasma);

// The box's simulation (lengths to metres, steps between frames rounded).
BoxFramesSpec boxFramesSpec(const Settings& plasma);

// The step of the strip's simulation the curtain shows at detail phase 0 … 1: phase × (frames − 1)
// frames, rounded to a step (the CPU frames interpolate between frames; the live run shows a step).
long curlsStep(const SheetFramesSpec& spec, double detailPhase);

// The box's frame position 0 … frames − 1 at the clock's time: the frames play over boxPlayS
// seconds, then again from the start.
double boxFramePosition(const Settings& plasma, double timeS);
// The same as a step of the box's simulation, rounded.
long boxStep(const Settings& plasma, double timeS);

} // namespace aurorawall::components::plasma
