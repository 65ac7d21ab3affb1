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

std::vector<char> fluxFramesBytes(const roles::FluxFrames& f)
{
    const std::int32_t counts[3] = {f.nx, f.ny, f.frames};
    const float texels[2] = {f.texelKmX, f.texelKmY};
    std::vector<char> bytes(sizeof counts + sizeof texels + f.flux.size() * sizeof(float));
    std::memcpy(bytes.data(), counts, sizeof counts);
    std::memcpy(bytes.data() + sizeof counts, texels, sizeof texels);
    std::memcpy(bytes.data() + sizeof counts + sizeof texels, f.flux.data(), f.flux.size() * sizeof(float));
    return bytes;
}

roles::FluxFrames fluxFramesFromBytes(const std::vector<char>& bytes, int nx, int ny, int frames, const std::string& what)
{
    std::int32_t counts[3];
    float texels[2];
    const std::size_t header = sizeof counts + sizeof texels;
    const std::size_t cells = std::size_t(nx) * std::size_t(ny) * std::size_t(frames);
    if (bytes.size() != header + cells * sizeof(float))
        throw std::runtime_error(what + " cache: the frames do not have the spec's size");
    std::memcpy(counts, bytes.data(), sizeof counts);
    std::memcpy(texels, bytes.data() + sizeof counts, sizeof texels);
    if (counts[0] != nx || counts[1] != ny || counts[2] != frames)
        throw std::runtime_error(what + " cache: the frames do not have the spec's size");
    roles::FluxFrames f;
    f.nx = counts[0];
    f.ny = counts[1];
    f.frames = counts[2];
    f.texelKmX = texels[0];
    f.texelKmY = texels[1];
    f.flux.resize(cells);
    std::memcpy(f.flux.data(), bytes.data() + header, cells * sizeof(float));
    return f;
}

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
                                            [&] { return fluxFramesBytes(simulation::simulateCurtainDetail(spec)); });
    return {fluxFramesFromBytes(table.bytes, spec.nx, spec.ny, spec.frames, "fluid_detail"), table.outcome};
}

} // namespace aurorawall::components::fluid_detail
