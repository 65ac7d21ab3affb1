#pragma once
// The fluid_detail component: small-scale curtain detail from the Kelvin-Helmholtz stable-fluids
// simulation (src/components/fluid_detail/simulation), simulated once at start-up and sampled by the aurora's curtain profile.
#include "components/fluid_detail/simulation/curtain_detail.h"
#include "scene/component.h"

namespace aurorawall::components::fluid_detail {

struct Settings : scene::SettingsOf<Settings> {
    static constexpr const char* kComponent = "fluid_detail";
    int cellsAlong = 512;
    int cellsAcross = 128;
    double stripLengthKm = 128.0;
    double stripWidthKm = 32.0;
    int frames = 16;
    unsigned seed = 1;
    // The pressure projection: an exact FFT solve (FFTW) or multigrid V-cycles (docs/fluid.md).
    simulation::PressureSolver pressureSolver = simulation::PressureSolver::Fft;
};

const scene::Component& component();

} // namespace aurorawall::components::fluid_detail
