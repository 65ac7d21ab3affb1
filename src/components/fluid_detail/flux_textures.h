#pragma once
// The curtain flux frames on the GPU, as shaders/components/aurora/curtain_profile.glsl reads them
// (fluid_detail's simulated frames, the plasma's electron strip): the flux itself (unit 3,
// uFluxFrames: x along, y across, z frame; linear, periodic) and its running integrals across the
// strip (unit 10, uFluxColumns: fluid::fluxColumns, entries at the cell centres across), which let a ray
// step be integrated across a thin curtain in closed form.
#include "components/fluid_detail/simulation/curtain_detail.h"
#include "gl/shader_program.h"
#include "gl/texture.h"

#include <glm/glm.hpp>

namespace aurorawall::components::fluid_detail {

class FluxTextures {
public:
    FluxTextures();

    // Both textures from these frames (made anew when a size changes, else rewritten in place).
    void upload(const fluid::FluxFrames& frames);
    // The textures and uFluxStrip = (strip length km, strip width km, frame count, peak scale).
    void bind(gl::Program& program, double stripLengthKm, double stripWidthKm, double peakScale) const;

private:
    gl::Texture frames_;
    gl::Texture columns_;
};

} // namespace aurorawall::components::fluid_detail
