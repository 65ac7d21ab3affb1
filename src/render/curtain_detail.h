#pragma once
// The fluid_detail component on the GPU: the Kelvin-Helmholtz flux frames of src/fluid as a 3D
// texture (along the curtain x, across it y, frame z; linear filtering, periodic along), with the
// constants that turn a lookup into a profile of peak 1. Simulated once per rank at start-up;
// the simulation is deterministic, so every rank holds the same frames.
#include "fluid/curtain_detail.h"
#include "gl/shader_program.h"
#include "gl/texture.h"
#include "scene/scene.h"

#include <string>

namespace aurorawall::render {

class CurtainDetail {
public:
    explicit CurtainDetail(const scene::FluidDetail& detail);

    // Texture unit 3 and the uniforms of shaders/aurora/curtain_profile.glsl.
    void bind(gl::Program& program) const;

    // Standard deviation of the curtain's flux across it in the simulation (km): a curtain of
    // thickness T samples the strip at u * fluxWidthKm / (T/2).
    double fluxWidthKm() const { return spec_.fluxWidthKm; }
    // Beyond this lateral distance (strip km) no frame holds more than 1e-3 of the peak.
    double reachKm() const { return reachKm_; }
    double stripLengthKm() const { return spec_.stripLengthKm; }

    const std::string& summary() const { return summary_; }

private:
    fluid::CurtainDetailSpec spec_;
    gl::Texture frames_;
    float peakScale_ = 1.0f;
    double reachKm_ = 0.0;
    std::string summary_;
};

// The simulation parameters for a scene's fluid_detail table (docs/fluid.md).
fluid::CurtainDetailSpec curtainDetailSpec(const scene::FluidDetail& detail);

} // namespace aurorawall::render
