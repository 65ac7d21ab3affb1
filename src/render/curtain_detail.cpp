#include "render/curtain_detail.h"

#include "common/constants.h"

#include <chrono>
#include <cmath>
#include <cstdio>

namespace aurorawall::render {

fluid::CurtainDetailSpec curtainDetailSpec(const scene::FluidDetail& detail)
{
    fluid::CurtainDetailSpec spec;
    spec.nx = detail.cellsAlong;
    spec.ny = detail.cellsAcross;
    spec.stripLengthKm = detail.stripLengthKm;
    spec.stripWidthKm = detail.stripWidthKm;
    spec.frames = detail.frames;
    spec.seed = detail.seed;
    return spec;
}

CurtainDetail::CurtainDetail(const scene::FluidDetail& detail)
    : spec_(curtainDetailSpec(detail)),
      frames_(gl::Texture::create3D(1, 1, 1, gl::TexelFormat::R32F, gl::Filter::Linear, gl::Wrap::Repeat))
{
    const auto start = std::chrono::steady_clock::now();
    const fluid::FluxFrames f = fluid::simulateCurtainDetail(spec_);
    frames_ = gl::Texture::create3D(f.nx, f.ny, f.frames, gl::TexelFormat::R32F, gl::Filter::Linear, gl::Wrap::Repeat);
    frames_.upload(f.flux);
    // Frame 0 is a Gaussian of standard deviation sigma with unit integral across: its peak is
    // 1/(sigma sqrt(2 pi)); scaling by sigma sqrt(2 pi) makes the smooth curtain's peak 1.
    peakScale_ = static_cast<float>(spec_.fluxWidthKm * std::sqrt(2.0 * kPi));
    float peak = 0.0f;
    for (float v : f.flux)
        peak = std::max(peak, v);
    for (int k = 0; k < f.frames; ++k)
        for (int iy = 0; iy < f.ny; ++iy)
            for (int ix = 0; ix < f.nx; ++ix)
                if (f.at(k, ix, iy) > 1e-3f * peak)
                    reachKm_ = std::max(reachKm_, std::abs((iy + 0.5) * f.texelKmY - 0.5 * spec_.stripWidthKm) +
                                                      f.texelKmY);
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    char text[160];
    std::snprintf(text, sizeof text, "fluid_detail: %d x %d cells, %d frames, reach %.1f km: %.0f ms", f.nx, f.ny,
                  f.frames, reachKm_, ms);
    summary_ = text;
}

void CurtainDetail::bind(gl::Program& program) const
{
    program.bindTexture("uFluxFrames", 3, frames_.id());
    program.set("uFluxStrip", glm::vec4(spec_.stripLengthKm, spec_.stripWidthKm, spec_.frames, peakScale_));
}

} // namespace aurorawall::render
