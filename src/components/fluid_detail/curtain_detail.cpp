#include "components/fluid_detail/curtain_detail.h"

#include "common/formatted.h"
#include "components/fluid_detail/cached_flux_frames.h"
#include "io/table_cache.h"
#include "physics/constants.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

namespace aurorawall::components::fluid_detail {

simulation::CurtainDetailSpec curtainDetailSpec(const Settings& detail)
{
    simulation::CurtainDetailSpec spec;
    spec.nx = detail.cellsAlong;
    spec.ny = detail.cellsAcross;
    spec.stripLengthKm = detail.stripLengthKm;
    spec.stripWidthKm = detail.stripWidthKm;
    spec.frames = detail.frames;
    spec.seed = detail.seed;
    spec.pressureSolver = detail.pressureSolver;
    return spec;
}

DetailShape detailShape(const simulation::CurtainDetailSpec& spec, const roles::FluxFrames& frames)
{
    DetailShape d;
    d.fluxWidthKm = spec.fluxWidthKm;
    d.setFrameReaches(roles::frameReachesKm(frames, spec.stripWidthKm));
    d.stripLengthKm = spec.stripLengthKm;
    d.peakScale = spec.fluxWidthKm * std::sqrt(2.0 * physics::kPi);
    return d;
}

CurtainDetail::CurtainDetail(const Settings& detail)
    : spec_(curtainDetailSpec(detail))
{
    const auto start = std::chrono::steady_clock::now();
    const CachedFluxFrames cached = cachedFluxFrames(spec_, io::defaultCacheDirectory());
    const roles::FluxFrames& f = cached.frames;
    columns_.upload(f);
    shape_ = detailShape(spec_, f);
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    summary_ = common::formatted("fluid_detail: %d x %d cells, %d frames, reach %.1f km, %s: %.0f ms", f.nx, f.ny,
                                 f.frames, shape_.reachKm, cached.outcome.c_str(), ms);
}

void CurtainDetail::bind(gl::Program& program) const
{
    columns_.bind(program, spec_.stripLengthKm, spec_.stripWidthKm, shape_.peakScale);
}

} // namespace aurorawall::components::fluid_detail
