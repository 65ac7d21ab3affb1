#include "components/plasma/simulation/electron_sheet.h"

#include "physics/constants.h"
#include "components/plasma/simulation/plasma_parameters.h"

#include <cmath>
#include <stdexcept>

namespace aurorawall::components::plasma::simulation {

double sheetTimeStep(const ElectronSheetSpec& spec)
{
    return spec.cyclotronFrequencyTimesDt / cyclotronFrequency(spec.magneticFieldT);
}

double diocotronFrequency(const ElectronSheetSpec& spec)
{
    return kElementaryCharge * spec.electronDensity / (kVacuumPermittivity * spec.magneticFieldT);
}

PeriodicGrid sheetGrid(const ElectronSheetSpec& spec)
{
    return PeriodicGrid(2, {spec.cellsAlong, spec.cellsAcross, 1},
                        {spec.lengthM / spec.cellsAlong, spec.widthM / spec.cellsAcross, 1.0});
}

Particles sheetElectrons(const ElectronSheetSpec& spec)
{
    if (!(spec.thicknessM > 0.0 && spec.thicknessM < spec.widthM) || spec.particlesPerCellPerAxis < 1 ||
        !(spec.electronDensity > 0.0) || !(spec.magneticFieldT > 0.0))
        throw std::invalid_argument("electron sheet: needs 0 < thickness < width, a density and B > 0, "
                                    "and at least one particle per cell");
    const PeriodicGrid grid = sheetGrid(spec);
    const int columns = spec.cellsAlong * spec.particlesPerCellPerAxis;
    const int rows = std::max(1, int(std::lround(spec.thicknessM / grid.spacing[1])) * spec.particlesPerCellPerAxis);
    const double bottom = 0.5 * (spec.widthM - spec.thicknessM);
    Particles p;
    // n_b over the strip's area per metre along z.
    p.weight = spec.electronDensity * spec.lengthM * spec.thicknessM / (double(columns) * rows);
    for (int j = 0; j < rows; ++j)
        for (int i = 0; i < columns; ++i) {
            const double x = (i + 0.5) * spec.lengthM / columns;
            double y = bottom + (j + 0.5) * spec.thicknessM / rows +
                       spec.seedDisplacementM * std::sin(2.0 * physics::kPi * spec.mode * x / spec.lengthM);
            y -= spec.widthM * std::floor(y / spec.widthM);
            p.position.push_back({x, y, 0.5});
            p.velocity.push_back(glm::dvec3(0.0));
        }
    return p;
}

ElectrostaticPic sheetSimulation(const ElectronSheetSpec& spec)
{
    return ElectrostaticPic(sheetGrid(spec), sheetElectrons(spec), {0.0, 0.0, spec.magneticFieldT},
                            sheetTimeStep(spec));
}

} // namespace aurorawall::components::plasma::simulation
