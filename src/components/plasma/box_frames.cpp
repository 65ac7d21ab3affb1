#include "physics/constants.h"
#include "components/plasma/box_frames.h"

#include "components/plasma/recorded_frames.h"
#include "components/plasma/simulation/electrostatic_pic.h"
#include "components/plasma/simulation/particle_mesh.h"
#include "components/plasma/simulation/plasma_parameters.h"
#include "io/table_cache.h"

#include <cmath>
#include <cstdio>
#include <cstring>
#include <stdexcept>

namespace aurorawall::components::plasma {

namespace pic = aurorawall::components::plasma::simulation;

namespace {

// Bump when the byte layout below changes.
constexpr int kBoxFormatVersion = 1;

// Every field of the spec must be in the key: a new field changes the size and stops the build here.
static_assert(sizeof(BoxFramesSpec) == 64, "add the new BoxFramesSpec field to boxFramesCacheKey");

double wavenumber(const BoxFramesSpec& s) { return 2.0 * physics::kPi * s.seedMode / s.sideM; }

std::vector<char> boxFramesBytes(const BoxFrames& f)
{
    std::vector<char> bytes(f.density.size() * sizeof(float));
    std::memcpy(bytes.data(), f.density.data(), bytes.size());
    return bytes;
}

} // namespace

pic::Particles boxElectrons(const BoxFramesSpec& s)
{
    const int n = s.cells * s.particlesPerCellAxis;
    const double spacing = s.sideM / n, k = wavenumber(s), v0 = boxBeamSpeed(s);
    pic::Particles p;
    p.weight = s.electronDensity * s.sideM * s.sideM * s.sideM / (2.0 * n * n * n);
    p.position.reserve(2 * std::size_t(n) * n * n);
    for (int beam = 0; beam < 2; ++beam)
        for (int iz = 0; iz < n; ++iz)
            for (int iy = 0; iy < n; ++iy)
                for (int ix = 0; ix < n; ++ix) {
                    const double x = (ix + 0.5) * spacing, y = (iy + 0.5) * spacing;
                    const double phase = physics::kPi * std::sin(2.0 * physics::kPi * x / s.sideM) * std::sin(2.0 * physics::kPi * y / s.sideM);
                    double z = (iz + 0.5) * spacing;
                    z += s.seedAmplitudeM * std::sin(k * z + phase);
                    z -= s.sideM * std::floor(z / s.sideM);
                    p.position.emplace_back(x, y, z);
                    p.velocity.emplace_back(0.0, 0.0, beam == 0 ? v0 : -v0);
                }
    return p;
}

pic::PeriodicGrid boxGrid(const BoxFramesSpec& s)
{
    const double spacing = s.sideM / s.cells;
    return pic::PeriodicGrid(3, {s.cells, s.cells, s.cells}, {spacing, spacing, spacing});
}

std::vector<float> boxFrameDensity(const BoxFramesSpec& s, const pic::PeriodicGrid& grid,
                                   const pic::Particles& electrons)
{
    const std::vector<double> deposit = pic::depositChargeDensityAtCellCentres(grid, electrons);
    std::vector<float> n;
    n.reserve(deposit.size());
    for (double v : deposit)
        n.push_back(static_cast<float>(1.0 - v / (pic::kElementaryCharge * s.electronDensity)));
    return n;
}

double boxBeamSpeed(const BoxFramesSpec& s)
{
    return std::sqrt(3.0 / 8.0) * pic::plasmaFrequency(s.electronDensity) / wavenumber(s);
}

BoxFrames simulateBoxFrames(const BoxFramesSpec& s)
{
    if (s.frames < 2 || s.stepsPerFrame < 1 || s.cells < 2)
        throw std::invalid_argument("plasma box frames: needs 2 cells, 2 frames and 1 step per frame");
    const pic::PeriodicGrid grid = boxGrid(s);
    pic::ElectrostaticPic sim(grid, boxElectrons(s), glm::dvec3(0.0, 0.0, s.magneticFieldT), s.timeStepS);
    BoxFrames f;
    f.cells = s.cells;
    f.frames = s.frames;
    f.density.reserve(grid.nodeCount() * s.frames);
    recordFrames(sim, s.frames, s.stepsPerFrame, f.density,
                 [&](const pic::Particles& electrons) { return boxFrameDensity(s, grid, electrons); });
    return f;
}

std::string boxFramesCacheKey(const BoxFramesSpec& s)
{
    char text[512];
    std::snprintf(text, sizeof text,
                  "plasma box frames v%d; cells %d; side %a m; density %a; B %a T; dt %a s; particles per cell "
                  "per axis %d; seed mode %d amplitude %a m; frames %d, %d steps each; executable %s",
                  kBoxFormatVersion, s.cells, s.sideM, s.electronDensity, s.magneticFieldT, s.timeStepS,
                  s.particlesPerCellAxis, s.seedMode, s.seedAmplitudeM, s.frames, s.stepsPerFrame,
                  io::executableDigest().c_str());
    return text;
}

CachedBoxFrames cachedBoxFrames(const BoxFramesSpec& s, const std::string& cacheDirectory)
{
    io::CachedTable table = io::cachedTable(cacheDirectory, "plasma-box", boxFramesCacheKey(s),
                                            [&] { return boxFramesBytes(simulateBoxFrames(s)); });
    BoxFrames f;
    f.cells = s.cells;
    f.frames = s.frames;
    f.density.resize(std::size_t(s.cells) * s.cells * s.cells * s.frames);
    if (table.bytes.size() != f.density.size() * sizeof(float))
        throw std::runtime_error("plasma box frames: the cached table has " + std::to_string(table.bytes.size()) +
                                 " bytes, expected " + std::to_string(f.density.size() * sizeof(float)));
    std::memcpy(f.density.data(), table.bytes.data(), table.bytes.size());
    return {std::move(f), table.outcome};
}

} // namespace aurorawall::components::plasma
