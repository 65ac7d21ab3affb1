// Lookup error of the deposition table against the exact double formula, for several resolutions
// (docs/aurora-physics.md, "Tables"). Prints a Markdown table.
#include "components/aurora/physics/deposition_table.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

using namespace aurorawall::components::aurora::physics;

namespace {

// Largest relative error at points between texels in both axes, where the exact rate is at least
// 1e-1, 1e-2 and 1e-4 (−10, −20, −40 dB) of that energy's maximum over altitude.
void sweep(const DepositionTableSpec& spec, const char* spectrumName)
{
    DepositionTable table = buildDepositionTable(spec);
    double worst40 = 0.0, worst20 = 0.0, worst10 = 0.0;
    for (double fj = 0.37; fj < spec.energyCount - 1; fj += 0.5) {
        double energy = std::exp(table.minLogEnergy + fj * table.logEnergyStep);
        double peak = 0.0;
        for (double z = spec.minAltitudeKm; z <= spec.maxAltitudeKm; z += 0.1)
            peak = std::max(peak, depositionRate(z, energy, spec.spectrum));
        for (double z = spec.minAltitudeKm + 0.13; z < spec.maxAltitudeKm; z += 0.37 * spec.altitudeStepKm) {
            double exact = depositionRate(z, energy, spec.spectrum);
            double error = std::abs(sampleDepositionTable(table, float(z), float(energy)) / exact - 1.0);
            if (exact >= 1e-4 * peak) worst40 = std::max(worst40, error);
            if (exact >= 1e-2 * peak) worst20 = std::max(worst20, error);
            if (exact >= 1e-1 * peak) worst10 = std::max(worst10, error);
        }
    }
    std::printf("| %s | %.2f km | %d | %.2e | %.2e | %.2e |\n", spectrumName, spec.altitudeStepKm, spec.energyCount,
                worst10, worst20, worst40);
}

} // namespace

int main()
{
    std::printf("| spectrum | altitude step | energies (0.5-50 keV) | max rel. error, >= -10 dB | >= -20 dB | >= -40 dB |\n");
    std::printf("|---|---|---|---|---|---|\n");
    for (double step : {2.0, 1.0, 0.5, 0.25}) {
        for (int energies : {32, 64, 128}) {
            DepositionTableSpec spec;
            spec.altitudeStepKm = step;
            spec.energyCount = energies;
            sweep(spec, "mono");
        }
    }
    DepositionTableSpec maxwellian;
    maxwellian.spectrum = Spectrum::Maxwellian;
    maxwellian.energyCount = 32;
    maxwellian.altitudeStepKm = 1.0;
    sweep(maxwellian, "maxwellian");
    return 0;
}
