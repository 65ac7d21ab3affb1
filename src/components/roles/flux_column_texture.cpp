#include "components/roles/flux_column_texture.h"

#include "components/roles/flux_columns.h"

namespace aurorawall::components::roles {

namespace {

// Filtered within a layer (along an entry's cells and between frames), never between layers; the ghost
// texels make the interpolation periodic, so the edges clamp.
gl::Texture tableTexture(int width, int frames, int layers)
{
    return gl::Texture::create2DArray(width, frames, layers, gl::TexelFormat::RGBA32F, gl::Filter::Linear,
                                      gl::Wrap::Clamp);
}

} // namespace

FluxColumnTexture::FluxColumnTexture() : tables_(tableTexture(1, 1, 1))
{
}

void FluxColumnTexture::upload(const FluxFrames& f)
{
    const FluxTables t = packFluxTables(fluxColumns(f), fluxRows(f));
    if (tables_.width() != t.width || tables_.height() != t.frames || tables_.depth() != t.layers)
        tables_ = tableTexture(t.width, t.frames, t.layers);
    tables_.upload(t.texels);
    layout_ = glm::vec4(t.nx, t.ny, t.columnTiles, t.rowTiles);
}

void FluxColumnTexture::bind(gl::Program& program, double stripLengthKm, double stripWidthKm, double peakScale) const
{
    program.bindTexture("uFluxTables", 3, tables_.id());
    program.set("uFluxStrip", glm::vec4(stripLengthKm, stripWidthKm, tables_.height(), peakScale));
    program.set("uFluxLayout", layout_);
}

} // namespace aurorawall::components::roles
