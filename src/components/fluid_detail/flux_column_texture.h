#pragma once
// The curtain flux frames on the GPU, as shaders/components/aurora/curtain_profile.glsl reads them
// (fluid_detail's simulated frames, the plasma's electron strip): their running integrals across the
// strip (fluid::fluxColumns; unit 3, uFluxColumns: a 2D array, x along, y frame, a layer per entry
// across; linear along and between frames, periodic along), from which the shader takes both the flux
// and its integral over a ray step. Bilinear within a layer reads 4 texels where a 3D texture read 8.
#include "components/fluid_detail/simulation/curtain_detail.h"
#include "gl/shader_program.h"
#include "gl/texture.h"

namespace aurorawall::components::fluid_detail {

class FluxColumnTexture {
public:
    FluxColumnTexture();

    // The table of these frames (a new texture when a size changes, else rewritten in place).
    void upload(const fluid::FluxFrames& frames);
    // The texture and uFluxStrip = (strip length km, strip width km, frame count, peak scale).
    void bind(gl::Program& program, double stripLengthKm, double stripWidthKm, double peakScale) const;

private:
    gl::Texture columns_;
};

} // namespace aurorawall::components::fluid_detail
