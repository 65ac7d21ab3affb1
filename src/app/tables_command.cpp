#include "app/tables_command.h"

#include "cli/command_line.h"
#include "cli/exit_status.h"
#include "components/aurora/physics/deposition_table.h"
#include "components/tools.h"

#include <cstdio>
#include <ostream>
#include <string>

namespace aurorawall::app {
namespace {

namespace po = boost::program_options;

constexpr double kMinEnergyKeV = 0.01;
constexpr double kMaxEnergyKeV = 1000.0;

// The tables: deposition (nullptr) and each component's table of a scene.
cli::Choices<const components::SceneTable*> tables()
{
    cli::Choices<const components::SceneTable*> choices = {{"deposition", nullptr}};
    for (const components::SceneTable& t : components::componentSceneTables())
        choices.push_back({t.name, &t});
    return choices;
}

std::string usage()
{
    std::string text = "Usage: aurorawall tables deposition --energy-kev E [--maxwellian]\n";
    for (const components::SceneTable& t : components::componentSceneTables())
        text += "       aurorawall tables " + std::string(t.name) + " --scene FILE\n";
    text += "deposition: CSV altitude_km,rate from 60 to 600 km every 0.5 km: the Lazarev energy deposition rate\n"
            "in keV cm^-3 s^-1 per erg cm^-2 s^-1 of incident energy flux, over the US Standard Atmosphere 1976\n"
            "(docs/aurora-physics.md).\n";
    for (const components::SceneTable& t : components::componentSceneTables())
        text += std::string(t.name) + ": " + t.description;
    return text + "Exit status: 0 success, 1 output not written or the scene not read, 2 usage error.\n";
}

// "NAME: the scene file whose NAME table to print", with every component's table.
std::string sceneHelp()
{
    std::string names;
    for (const components::SceneTable& t : components::componentSceneTables())
        names += (names.empty() ? "" : " or ") + std::string(t.name);
    return names + ": the scene file whose " + names + " table to print";
}

void printDeposition(double energyKeV, bool maxwellian, std::ostream& out)
{
    const aurora::Spectrum spectrum = maxwellian ? aurora::Spectrum::Maxwellian : aurora::Spectrum::Monoenergetic;
    out << "altitude_km,rate\n";
    for (int i = 0; i <= 1080; ++i) {
        const double altitudeKm = 60.0 + 0.5 * i;
        char line[64];
        std::snprintf(line, sizeof line, "%.1f,%.10g\n", altitudeKm, aurora::depositionRate(altitudeKm, energyKeV, spectrum));
        out << line;
    }
}

} // namespace

int runTablesCommand(int argc, char** argv, std::ostream& out, std::ostream& err)
{
    return cli::runCommand("tables", out, err, [&] {
        cli::CommandLine cli("tables", usage());
        double energyKeV = 0.0;
        bool maxwellian = false;
        std::string tableName, sceneFile;
        cli.add()("energy-kev", po::value<double>(&energyKeV),
                  "electron energy E in keV (0.01 to 1000; Lazarev's fit is meant for 1-30 keV)")(
            "maxwellian", po::bool_switch(&maxwellian),
            "a Maxwellian spectrum with characteristic energy E (number flux ~ E exp(-E/E0)) instead of electrons "
            "all at E")("scene", po::value<std::string>(&sceneFile), sceneHelp().c_str());
        cli.addPositional("table", &tableName);
        if (!cli.parse(argc, argv)) {
            out << cli.help();
            return;
        }
        const cli::Choices<const components::SceneTable*> choices = tables();
        const components::SceneTable* table = nullptr;
        if (tableName.empty())
            throw cli.usageError("missing the table name (allowed: " + cli::wordsOf(choices) + ")");
        if (!cli::findChoice(choices, tableName, table))
            throw cli.usageError("unknown table '" + echoedInput(tableName) + "' (allowed: " + cli::wordsOf(choices) + ")");
        if (table) {
            if (sceneFile.empty() || cli.given("energy-kev") || maxwellian)
                throw cli.usageError(std::string(table->name) + " takes --scene FILE and nothing else");
            table->print(sceneFile, out);
            return;
        }
        if (!cli.given("energy-kev") || cli.given("scene"))
            throw cli.usageError("deposition takes --energy-kev E [--maxwellian]");
        if (!(energyKeV >= kMinEnergyKeV && energyKeV <= kMaxEnergyKeV)) {
            char got[32];
            std::snprintf(got, sizeof got, "%g", energyKeV);
            throw cli.usageError("--energy-kev must be between 0.01 and 1000 keV (got " + std::string(got) + ")");
        }
        printDeposition(energyKeV, maxwellian, out);
    });
}

} // namespace aurorawall::app
