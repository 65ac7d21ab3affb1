#pragma once
// The curtain flux frames on the GPU, as shaders/components/aurora/curtain_profile.glsl reads them
// (fluid_detail's simulated frames, the plasma's electron strip): their running integrals across the
// strip (fluxColumns), for a ray step that crosses a curtain, and along it (fluxRows), for
// one that runs along a curtain, packed into one 2D array texture (packFluxTables; unit 3,
// uFluxTables: x through an entry's cells, y frame, linear within a layer) so that the shader reads both
// through one code path. Bilinear within a layer reads 4 texels where a 3D texture read 8.
#include "components/roles/flux_frames.h"
#include "gl/shader_program.h"
#include "gl/texture.h"

#include <glm/glm.hpp>

namespace aurorawall::components::roles {

class FluxColumnTexture {
public:
    FluxColumnTexture();

    // The tables of these frames (a new texture when a size changes, else rewritten in place).
    void upload(const FluxFrames& frames);
    // The texture, uFluxStrip = (strip length km, strip width km, frame count, peak scale) and
    // uFluxLayout = (cells along, cells across, column entries per layer, row entries per layer).
    void bind(gl::Program& program, double stripLengthKm, double stripWidthKm, double peakScale) const;

private:
    gl::Texture tables_;
    glm::vec4 layout_{0.0f};
};

} // namespace aurorawall::components::roles
