#include "aurora/tables_cli.h"

#include "aurora/deposition_table.h"

#include <boost/program_options.hpp>
#include <cmath>
#include <cstdio>
#include <ostream>
#include <string>

namespace aurorawall::aurora {
namespace {

namespace po = boost::program_options;

constexpr int kUsageError = 2;
constexpr double kMinEnergyKeV = 0.01;
constexpr double kMaxEnergyKeV = 1000.0;

} // namespace

int runTablesCommand(int argc, char** argv, std::ostream& out, std::ostream& err)
{
    po::options_description options(
        "Usage: aurorawall tables deposition --energy-kev E [--maxwellian]\n"
        "Prints CSV altitude_km,rate from 60 to 600 km every 0.5 km: the Lazarev energy deposition rate\n"
        "in keV cm^-3 s^-1 per erg cm^-2 s^-1 of incident energy flux, over the US Standard Atmosphere 1976\n"
        "(docs/aurora-physics.md). Exit status 2 and one error line for a bad option.\nOptions");
    double energyKeV = 0.0;
    options.add_options()("help,h", "show this help")(
        "energy-kev", po::value<double>(&energyKeV)->required(),
        "electron energy E in keV (0.01 to 1000; Lazarev's fit is meant for 1-30 keV)")(
        "maxwellian", "a Maxwellian spectrum with characteristic energy E (number flux ~ E exp(-E/E0)) "
                      "instead of electrons all at E");
    po::positional_options_description positional;
    positional.add("table", 1);
    po::options_description hidden;
    std::string table;
    hidden.add_options()("table", po::value<std::string>(&table));
    po::options_description all;
    all.add(options).add(hidden);

    po::variables_map variables;
    try {
        po::store(po::command_line_parser(argc, argv).options(all).positional(positional).run(), variables);
        if (variables.count("help")) {
            out << options;
            return 0;
        }
        po::notify(variables);
    } catch (const po::error& e) {
        err << "aurorawall tables: " << e.what() << "\n";
        return kUsageError;
    }
    if (table.empty()) {
        err << "aurorawall tables: missing the table name (expected: deposition)\n";
        return kUsageError;
    }
    if (table != "deposition") {
        err << "aurorawall tables: unknown table '" << table << "' (expected: deposition)\n";
        return kUsageError;
    }
    if (!(energyKeV >= kMinEnergyKeV && energyKeV <= kMaxEnergyKeV)) {
        err << "aurorawall tables: --energy-kev must be between 0.01 and 1000 keV (got " << energyKeV << ")\n";
        return kUsageError;
    }
    Spectrum spectrum = variables.count("maxwellian") ? Spectrum::Maxwellian : Spectrum::Monoenergetic;
    out << "altitude_km,rate\n";
    for (int i = 0; i <= 1080; ++i) {
        double altitudeKm = 60.0 + 0.5 * i;
        char line[64];
        std::snprintf(line, sizeof line, "%.1f,%.10g\n", altitudeKm, depositionRate(altitudeKm, energyKeV, spectrum));
        out << line;
    }
    return 0;
}

} // namespace aurorawall::aurora
