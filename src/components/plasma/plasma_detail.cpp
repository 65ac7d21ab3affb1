#include "components/plasma/plasma_detail.h"

#include "common/data_dir.h"
#include "common/formatted.h"
#include "components/plasma/simulation/plasma_parameters.h"
#include "gl/functions.h"
#include "gl/shader_program.h"
#include "io/table_cache.h"

#include <chrono>
#include <cstdio>

namespace aurorawall::components::plasma {

namespace pic = aurorawall::components::plasma::simulation;

PlasmaDetail::PlasmaDetail(const Settings& plasma, const scene::Scene& scene)
    : spec_(sheetFramesSpec(plasma)), phase_(roles::firstCurtainDetailPhase(scene, spec_.sheet.lengthM * 1e-3))
{
    const auto start = std::chrono::steady_clock::now();
    roles::FluxFrames f;
    std::string outcome;
    if (plasma.device == Settings::Device::Gpu) {
        // Frame 0 on the CPU gives the curtain's shape, as the CPU frames' frame 0 does.
        const pic::PeriodicGrid grid = pic::sheetGrid(spec_.sheet);
        const pic::Particles electrons = pic::sheetElectrons(spec_.sheet);
        f.nx = grid.cells[0];
        f.ny = grid.cells[1];
        f.frames = 1;
        f.texelKmX = static_cast<float>(grid.spacing[0] * 1e-3);
        f.texelKmY = static_cast<float>(grid.spacing[1] * 1e-3);
        f.flux = sheetFrameDensity(spec_, grid, electrons);
        const SheetFramesSpec spec = spec_;
        live_ = std::make_unique<LivePic>(
            grid, electrons, glm::dvec3(0.0, 0.0, spec_.sheet.magneticFieldT), pic::sheetTimeStep(spec_.sheet),
            [spec](const pic::PeriodicGrid& g, const pic::Particles& e) { return sheetFrameDensity(spec, g, e); },
            common::dataDirectory() + "/shaders");
        outcome = "live on the GPU";
    } else {
        CachedSheetFrames cached = cachedSheetFrames(spec_, io::defaultCacheDirectory());
        f = std::move(cached.frames);
        outcome = cached.outcome;
    }
    columns_.upload(f);
    shape_ = sheetDetailShape(spec_, f);
    // The live strip's later steps are not known at start-up: the curtain reaches as far as the
    // strip's box across (the shader samples nothing beyond it).
    if (live_) {
        shape_.reachKm = 0.5 * spec_.sheet.widthM * 1e-3;
        shape_.frameReachKm.clear();
        liveFrame_ = f;
    }
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    const double wc = pic::cyclotronFrequency(spec_.sheet.magneticFieldT);
    const double wp = pic::plasmaFrequency(spec_.sheet.electronDensity);
    const double dt = pic::sheetTimeStep(spec_.sheet);
    summary_ = common::formatted(
                  "plasma: %d x %d cells, %d frames of %d steps, wc_dt %.3g, wp_dt %.3g, reach %.1f km, %s: %.0f ms",
                  f.nx, f.ny, spec_.frames, spec_.stepsPerFrame, wc * dt, wp * dt, shape_.reachKm, outcome.c_str(),
                  ms);
}

void PlasmaDetail::setFrame(gl::Program&, const cluster::FrameState& frame)
{
    if (!live_)
        return;
    live_->showStep(curlsStep(spec_, phase_(frame.timeS)), [this](const std::vector<float>& density) {
        liveFrame_.flux = density;
        columns_.upload(liveFrame_);
    });
}

void PlasmaDetail::bind(gl::Program& program) const
{
    columns_.bind(program, spec_.sheet.lengthM * 1e-3, spec_.sheet.widthM * 1e-3, shape_.peakScale);
}

} // namespace aurorawall::components::plasma
