#include "components/plasma/sheet_frames.h"

#include "components/plasma/recorded_frames.h"
#include "components/plasma/simulation/particle_mesh.h"
#include "components/plasma/simulation/plasma_parameters.h"
#include "io/table_cache.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <stdexcept>

namespace aurorawall::components::plasma {

namespace pic = aurorawall::components::plasma::simulation;

namespace {

// Bump when the byte layout below changes.
constexpr int kFormatVersion = 1;

// Every field of the spec must be in the key: a new field changes the size and stops the build here.
static_assert(sizeof(SheetFramesSpec) == 80, "add the new SheetFramesSpec field to sheetFramesCacheKey");

} // namespace

std::vector<float> sheetFrameDensity(const SheetFramesSpec& spec, const pic::PeriodicGrid& grid,
                                     const pic::Particles& electrons)
{
    // The density (m⁻³) at the cell centres: the CIC deposit of the electrons moved back by half a
    // cell, plus the background the deposit's mean removal took away.
    const std::vector<double> deposit = pic::depositChargeDensityAtCellCentres(grid, electrons);
    const glm::dvec3 box = grid.boxLength();
    const double mean = electrons.weight * double(electrons.position.size()) / (box.x * box.y * box.z);
    const double perKm = 1.0 / (spec.sheet.electronDensity * spec.sheet.thicknessM * 1e-3);
    std::vector<float> frame;
    frame.reserve(deposit.size());
    for (double v : deposit)
        frame.push_back(static_cast<float>((mean - v / pic::kElementaryCharge) * perKm));
    return frame;
}

roles::FluxFrames simulateSheetFrames(const SheetFramesSpec& spec)
{
    if (spec.frames < 2 || spec.stepsPerFrame < 1)
        throw std::invalid_argument("plasma frames: needs at least 2 frames and 1 step per frame");
    pic::ElectrostaticPic sim = pic::sheetSimulation(spec.sheet);
    const pic::PeriodicGrid& grid = sim.grid();
    roles::FluxFrames f;
    f.nx = grid.cells[0];
    f.ny = grid.cells[1];
    f.frames = spec.frames;
    f.texelKmX = static_cast<float>(grid.spacing[0] * 1e-3);
    f.texelKmY = static_cast<float>(grid.spacing[1] * 1e-3);
    f.flux.reserve(grid.nodeCount() * spec.frames);
    recordFrames(sim, spec.frames, spec.stepsPerFrame, f.flux,
                 [&](const pic::Particles& electrons) { return sheetFrameDensity(spec, grid, electrons); });
    return f;
}

roles::DetailShape sheetDetailShape(const SheetFramesSpec& spec, const roles::FluxFrames& f)
{
    const double widthKm = spec.sheet.widthM * 1e-3;
    double peak = 0.0, integral = 0.0, second = 0.0;
    for (int iy = 0; iy < f.ny; ++iy) {
        const double u = (iy + 0.5) * f.texelKmY - 0.5 * widthKm;
        for (int ix = 0; ix < f.nx; ++ix) {
            const double v = f.at(0, ix, iy);
            peak = std::max(peak, v);
            integral += v;
            second += v * u * u;
        }
    }
    roles::DetailShape d;
    d.fluxWidthKm = std::sqrt(second / integral);
    d.setFrameReaches(roles::frameReachesKm(f, widthKm));
    d.stripLengthKm = spec.sheet.lengthM * 1e-3;
    d.peakScale = 1.0 / peak;
    return d;
}

std::string sheetFramesCacheKey(const SheetFramesSpec& s)
{
    const pic::ElectronSheetSpec& e = s.sheet;
    char text[768];
    std::snprintf(text, sizeof text,
                  "plasma sheet frames v%d; cells %d x %d; box %a x %a m; thickness %a m; density %a; B %a T; "
                  "wc_dt %a; particles per cell per axis %d; seed mode %d displacement %a m; frames %d, %d steps "
                  "each; executable %s",
                  kFormatVersion, e.cellsAlong, e.cellsAcross, e.lengthM, e.widthM, e.thicknessM, e.electronDensity,
                  e.magneticFieldT, e.cyclotronFrequencyTimesDt, e.particlesPerCellPerAxis, e.mode,
                  e.seedDisplacementM, s.frames, s.stepsPerFrame, io::executableDigest().c_str());
    return text;
}

CachedSheetFrames cachedSheetFrames(const SheetFramesSpec& spec, const std::string& cacheDirectory)
{
    io::CachedTable table = io::cachedTable(cacheDirectory, "plasma", sheetFramesCacheKey(spec),
                                            [&] { return roles::fluxFramesBytes(simulateSheetFrames(spec)); });
    return {roles::fluxFramesFromBytes(table.bytes, spec.sheet.cellsAlong, spec.sheet.cellsAcross, spec.frames, "plasma"),
            table.outcome};
}

} // namespace aurorawall::components::plasma
