#include "app/tables_command.h"

#include "app/cli/command_line.h"
#include "app/cli/exit_status.h"
#include "components/aurora/physics/deposition_table.h"

#include <cstdio>
#include <ostream>
#include <string>

namespace aurorawall::app {
namespace {

namespace po = boost::program_options;

constexpr double kMinEnergyKeV = 0.01;
constexpr double kMaxEnergyKeV = 1000.0;

enum class Table { Deposition };
const cli::Choices<Table> kTables = {{"deposition", Table::Deposition}};

} // namespace

int runTablesCommand(int argc, char** argv, std::ostream& out, std::ostream& err)
{
    return cli::runCommand("tables", out, err, [&] {
        cli::CommandLine cli(
            "tables",
            "Usage: aurorawall tables deposition --energy-kev E [--maxwellian]\n"
            "Prints CSV altitude_km,rate from 60 to 600 km every 0.5 km: the Lazarev energy deposition rate\n"
            "in keV cm^-3 s^-1 per erg cm^-2 s^-1 of incident energy flux, over the US Standard Atmosphere 1976\n"
            "(docs/aurora-physics.md). Exit status: 0 success, 1 output not written, 2 usage error.\n");
        double energyKeV = 0.0;
        bool maxwellian = false;
        std::string tableName;
        cli.add()("energy-kev", po::value<double>(&energyKeV)->required(),
                  "electron energy E in keV (0.01 to 1000; Lazarev's fit is meant for 1-30 keV)")(
            "maxwellian", po::bool_switch(&maxwellian),
            "a Maxwellian spectrum with characteristic energy E (number flux ~ E exp(-E/E0)) instead of electrons "
            "all at E");
        cli.addPositional("table", &tableName);
        if (!cli.parse(argc, argv)) {
            out << cli.help();
            return;
        }
        Table table = Table::Deposition;
        if (tableName.empty())
            throw cli.usageError("missing the table name (allowed: " + cli::wordsOf(kTables) + ")");
        if (!cli::findChoice(kTables, tableName, table))
            throw cli.usageError("unknown table '" + tableName + "' (allowed: " + cli::wordsOf(kTables) + ")");
        if (!(energyKeV >= kMinEnergyKeV && energyKeV <= kMaxEnergyKeV)) {
            char got[32];
            std::snprintf(got, sizeof got, "%g", energyKeV);
            throw cli.usageError("--energy-kev must be between 0.01 and 1000 keV (got " + std::string(got) + ")");
        }
        const aurora::Spectrum spectrum = maxwellian ? aurora::Spectrum::Maxwellian : aurora::Spectrum::Monoenergetic;
        out << "altitude_km,rate\n";
        for (int i = 0; i <= 1080; ++i) {
            const double altitudeKm = 60.0 + 0.5 * i;
            char line[64];
            std::snprintf(line, sizeof line, "%.1f,%.10g\n", altitudeKm,
                          aurora::depositionRate(altitudeKm, energyKeV, spectrum));
            out << line;
        }
    });
}

} // namespace aurorawall::app
