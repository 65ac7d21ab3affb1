#include "components/fluid_detail/cached_flux_frames.h"

#include "io/table_cache.h"

#include <cstdint>
#include <cstdio>
#include <cstring>
#include <stdexcept>

namespace aurorawall::components::fluid_detail {

namespace {

// Bump when the byte layout below changes.
constexpr int kFormatVersion = 1;

// Every field of the spec must be in the key: a field added to the spec changes its size and
// stops the build here until it is added to fluxFramesCacheKey.
static_assert(sizeof(simulation::CurtainDetailSpec) == 104, "add the new CurtainDetailSpec field to fluxFramesCacheKey");

} // namespace

std::string fluxFramesCacheKey(const simulation::CurtainDetailSpec& s)
{
    char text[768];
    std::snprintf(text, sizeof text,
                  "fluid_detail flux frames v%d; nx %d ny %d; strip %a x %a km; shear %a km/s over %a km; "
                  "flux width %a km; perturbation %a; frames %d, %a s apart, %d steps each; solver %s, "
                  "multigrid cycles %d tolerance %a; seed %u; executable %s",
                  kFormatVersion, s.nx, s.ny, s.stripLengthKm, s.stripWidthKm, s.shearVelocity, s.shearThicknessKm,
                  s.fluxWidthKm, s.perturbation, s.frames, s.timeBetweenFramesS, s.stepsPerFrame,
                  s.pressureSolver == simulation::PressureSolver::Fft ? "fft" : "multigrid", s.multigridCycles,
                  s.multigridTolerance, static_cast<unsigned>(s.seed), io::executableDigest().c_str());
    return text;
}

CachedFluxFrames cachedFluxFrames(const simulation::CurtainDetailSpec& spec, const std::string& cacheDirectory)
{
    io::CachedTable table = io::cachedTable(cacheDirectory, "fluid_detail", fluxFramesCacheKey(spec),
                                            [&] { return roles::fluxFramesBytes(simulation::simulateCurtainDetail(spec)); });
    return {roles::fluxFramesFromBytes(table.bytes, spec.nx, spec.ny, spec.frames, "fluid_detail"), table.outcome};
}

} // namespace aurorawall::components::fluid_detail
