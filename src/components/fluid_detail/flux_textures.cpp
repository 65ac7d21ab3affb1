#include "components/fluid_detail/flux_textures.h"

#include "components/fluid_detail/simulation/flux_columns.h"

namespace aurorawall::components::fluid_detail {

namespace {

gl::Texture fluxTexture(int nx, int ny, int frames, gl::TexelFormat format)
{
    return gl::Texture::create3D(nx, ny, frames, format, gl::Filter::Linear, gl::Wrap::Repeat);
}

} // namespace

FluxTextures::FluxTextures()
    : frames_(fluxTexture(1, 1, 1, gl::TexelFormat::R32F)), columns_(fluxTexture(1, 2, 1, gl::TexelFormat::RGBA32F))
{
}

void FluxTextures::upload(const fluid::FluxFrames& f)
{
    const fluid::FluxColumns c = fluid::fluxColumns(f);
    if (frames_.width() != f.nx || frames_.height() != f.ny || frames_.depth() != f.frames) {
        frames_ = fluxTexture(f.nx, f.ny, f.frames, gl::TexelFormat::R32F);
        columns_ = fluxTexture(c.nx, c.rows, c.frames, gl::TexelFormat::RGBA32F);
    }
    frames_.upload(f.flux);
    columns_.upload(c.texels);
}

void FluxTextures::bind(gl::Program& program, double stripLengthKm, double stripWidthKm, double peakScale) const
{
    program.bindTexture("uFluxFrames", 3, frames_.id());
    program.bindTexture("uFluxColumns", 10, columns_.id());
    program.set("uFluxStrip", glm::vec4(stripLengthKm, stripWidthKm, frames_.depth(), peakScale));
}

} // namespace aurorawall::components::fluid_detail
