#include "components/fluid_detail/flux_column_texture.h"

#include "components/fluid_detail/simulation/flux_columns.h"

#include <glm/glm.hpp>

namespace aurorawall::components::fluid_detail {

namespace {

gl::Texture columnTexture(int nx, int rows, int frames)
{
    return gl::Texture::create3D(nx, rows, frames, gl::TexelFormat::RGBA32F, gl::Filter::Linear, gl::Wrap::Repeat);
}

} // namespace

FluxColumnTexture::FluxColumnTexture() : columns_(columnTexture(1, 2, 1))
{
}

void FluxColumnTexture::upload(const fluid::FluxFrames& f)
{
    const fluid::FluxColumns c = fluid::fluxColumns(f);
    if (columns_.width() != c.nx || columns_.height() != c.rows || columns_.depth() != c.frames)
        columns_ = columnTexture(c.nx, c.rows, c.frames);
    columns_.upload(c.texels);
}

void FluxColumnTexture::bind(gl::Program& program, double stripLengthKm, double stripWidthKm, double peakScale) const
{
    program.bindTexture("uFluxColumns", 3, columns_.id());
    program.set("uFluxStrip", glm::vec4(stripLengthKm, stripWidthKm, columns_.depth(), peakScale));
}

} // namespace aurorawall::components::fluid_detail
