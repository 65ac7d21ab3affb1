#include "components/plasma/plasma_detail.h"

#include "components/plasma/simulation/plasma_parameters.h"
#include "gl/shader_program.h"
#include "io/table_cache.h"

#include <chrono>
#include <cstdio>

namespace aurorawall::components::plasma {

PlasmaDetail::PlasmaDetail(const Settings& plasma)
    : spec_(sheetFramesSpec(plasma)),
      frames_(gl::Texture::create3D(1, 1, 1, gl::TexelFormat::R32F, gl::Filter::Linear, gl::Wrap::Repeat))
{
    const auto start = std::chrono::steady_clock::now();
    const CachedSheetFrames cached = cachedSheetFrames(spec_, io::defaultCacheDirectory());
    const fluid::FluxFrames& f = cached.frames;
    frames_ = gl::Texture::create3D(f.nx, f.ny, f.frames, gl::TexelFormat::R32F, gl::Filter::Linear, gl::Wrap::Repeat);
    frames_.upload(f.flux);
    shape_ = sheetDetailShape(spec_, f);
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    const double wc = aurorawall::plasma::cyclotronFrequency(spec_.sheet.magneticFieldT);
    const double wp = aurorawall::plasma::plasmaFrequency(spec_.sheet.electronDensity);
    const double dt = aurorawall::plasma::sheetTimeStep(spec_.sheet);
    char text[400];
    std::snprintf(text, sizeof text,
                  "plasma: %d x %d cells, %d frames of %d steps, wc_dt %.3g, wp_dt %.3g, reach %.1f km, %s: %.0f ms",
                  f.nx, f.ny, f.frames, spec_.stepsPerFrame, wc * dt, wp * dt, shape_.reachKm, cached.outcome.c_str(),
                  ms);
    summary_ = text;
}

void PlasmaDetail::bind(gl::Program& program) const
{
    program.bindTexture("uFluxFrames", 3, frames_.id());
    program.set("uFluxStrip", glm::vec4(spec_.sheet.lengthM * 1e-3, spec_.sheet.widthM * 1e-3, spec_.frames,
                                        static_cast<float>(shape_.peakScale)));
}

} // namespace aurorawall::components::plasma
