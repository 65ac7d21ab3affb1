#include "components/fluid_detail/flux_column_texture.h"

#include "components/fluid_detail/simulation/flux_columns.h"

#include <glm/glm.hpp>

namespace aurorawall::components::fluid_detail {

namespace {

// A layer per entry across: filtered along and between frames, never between entries.
gl::Texture columnTexture(int nx, int frames, int rows)
{
    return gl::Texture::create2DArray(nx, frames, rows, gl::TexelFormat::RGBA32F, gl::Filter::Linear, gl::Wrap::Repeat);
}

} // namespace

FluxColumnTexture::FluxColumnTexture() : columns_(columnTexture(1, 1, 2))
{
}

void FluxColumnTexture::upload(const fluid::FluxFrames& f)
{
    const fluid::FluxColumns c = fluid::fluxColumns(f);
    if (columns_.width() != c.nx || columns_.height() != c.frames || columns_.depth() != c.rows)
        columns_ = columnTexture(c.nx, c.frames, c.rows);
    columns_.upload(c.texels);
}

void FluxColumnTexture::bind(gl::Program& program, double stripLengthKm, double stripWidthKm, double peakScale) const
{
    program.bindTexture("uFluxColumns", 3, columns_.id());
    program.set("uFluxStrip", glm::vec4(stripLengthKm, stripWidthKm, columns_.height(), peakScale));
}

} // namespace aurorawall::components::fluid_detail
