#include "components/aurora/tools/deposition_table.h"

#include "components/aurora/physics/deposition_table.h"

#include <cstdio>
#include <memory>
#include <ostream>
#include <string>

namespace aurorawall::components::aurora::tools {

namespace {

namespace po = boost::program_options;

constexpr double kMinEnergyKeV = 0.01;
constexpr double kMaxEnergyKeV = 1000.0;

void printDeposition(double energyKeV, bool maxwellian, std::ostream& out)
{
    using physics::Spectrum;
    const Spectrum spectrum = maxwellian ? Spectrum::Maxwellian : Spectrum::Monoenergetic;
    out << "altitude_km,rate\n";
    for (int i = 0; i <= 1080; ++i) {
        const double altitudeKm = 60.0 + 0.5 * i;
        char line[64];
        std::snprintf(line, sizeof line, "%.1f,%.10g\n", altitudeKm,
                      physics::depositionRate(altitudeKm, energyKeV, spectrum));
        out << line;
    }
}

std::function<void(std::ostream&)> declare(cli::CommandLine& cli)
{
    struct Values {
        double energyKeV = 0.0;
        bool maxwellian = false;
    };
    auto values = std::make_shared<Values>();
    cli.add()("energy-kev", po::value<double>(&values->energyKeV),
              "electron energy E in keV (0.01 to 1000; Lazarev's fit is meant for 1-30 keV)")(
        "maxwellian", po::bool_switch(&values->maxwellian),
        "a Maxwellian spectrum with characteristic energy E (number flux ~ E exp(-E/E0)) instead of electrons "
        "all at E");
    return [values, &cli](std::ostream& out) {
        if (!(values->energyKeV >= kMinEnergyKeV && values->energyKeV <= kMaxEnergyKeV)) {
            char got[32];
            std::snprintf(got, sizeof got, "%g", values->energyKeV);
            throw cli.usageError("--energy-kev must be between 0.01 and 1000 keV (got " + std::string(got) + ")");
        }
        printDeposition(values->energyKeV, values->maxwellian, out);
    };
}

} // namespace

const OptionTable& depositionTable()
{
    static const OptionTable table{
        "deposition", "--energy-kev E [--maxwellian]",
        "CSV altitude_km,rate from 60 to 600 km every 0.5 km: the Lazarev energy deposition rate\n"
        "in keV cm^-3 s^-1 per erg cm^-2 s^-1 of incident energy flux, over the US Standard Atmosphere 1976\n"
        "(docs/aurora-physics.md).\n",
        {"energy-kev", "maxwellian"},
        {"energy-kev"},
        declare};
    return table;
}

} // namespace aurorawall::components::aurora::tools
