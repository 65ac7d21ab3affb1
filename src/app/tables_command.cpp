#include "common/constants.h"
#include "app/tables_command.h"

#include "app/cli/command_line.h"
#include "app/cli/exit_status.h"
#include "components/aurora/physics/deposition_table.h"
#include "components/glory/glory.h"
#include "components/registry.h"

#include <cstdio>
#include <stdexcept>
#include <ostream>
#include <string>

namespace aurorawall::app {
namespace {

namespace po = boost::program_options;

constexpr double kMinEnergyKeV = 0.01;
constexpr double kMaxEnergyKeV = 1000.0;

enum class Table { Deposition, Glory };
const cli::Choices<Table> kTables = {{"deposition", Table::Deposition}, {"glory", Table::Glory}};

// The glory's smeared phase table of a scene and its colour: CSV gamma_deg, P at each table
// wavelength, then the colour's linear sRGB per unit of the deck's geometric factor (cd/m^2).
void printGloryTable(const std::string& sceneFile, std::ostream& out)
{
    const scene::Scene scene = components::loadScene(sceneFile);
    if (!scene.has("glory"))
        throw std::runtime_error(sceneFile + ": the scene does not list glory");
    const auto& settings = scene.settings<components::glory::Settings>();
    const glory::PhaseTable table = components::glory::gloryTables(settings).phase;
    const std::vector<glm::dvec3> rgb = glory::gloryLinearSrgb(glory::gloryXyz(table, settings.light));
    out << "gamma_deg";
    for (double nm : table.wavelengthsNm) {
        char name[32];
        std::snprintf(name, sizeof name, ",p_%gnm", nm);
        out << name;
    }
    out << ",r,g,b\n";
    for (int a = 0; a < table.angles.size(); ++a) {
        char cell[40];
        std::snprintf(cell, sizeof cell, "%.6f", table.angles.angle(a) / kDegree);
        out << cell;
        for (size_t w = 0; w < table.wavelengthsNm.size(); ++w) {
            std::snprintf(cell, sizeof cell, ",%.8g", table.at(int(w), a));
            out << cell;
        }
        std::snprintf(cell, sizeof cell, ",%.8g,%.8g,%.8g\n", rgb[size_t(a)].r, rgb[size_t(a)].g, rgb[size_t(a)].b);
        out << cell;
    }
}

} // namespace

int runTablesCommand(int argc, char** argv, std::ostream& out, std::ostream& err)
{
    return cli::runCommand("tables", out, err, [&] {
        cli::CommandLine cli(
            "tables",
            "Usage: aurorawall tables deposition --energy-kev E [--maxwellian]\n"
            "       aurorawall tables glory --scene FILE\n"
            "deposition: CSV altitude_km,rate from 60 to 600 km every 0.5 km: the Lazarev energy deposition rate\n"
            "in keV cm^-3 s^-1 per erg cm^-2 s^-1 of incident energy flux, over the US Standard Atmosphere 1976\n"
            "(docs/aurora-physics.md).\n"
            "glory: CSV gamma_deg, p_<L>nm at each table wavelength, r, g, b: the scene's glory table (the drops'\n"
            "size-averaged phase function, smeared by the light's disc) at each angle from the antisolar point,\n"
            "and its colour per unit of the deck's geometric factor (docs/GLORY.md).\n"
            "Exit status: 0 success, 1 output not written or the scene not read, 2 usage error.\n");
        double energyKeV = 0.0;
        bool maxwellian = false;
        std::string tableName, sceneFile;
        cli.add()("energy-kev", po::value<double>(&energyKeV),
                  "electron energy E in keV (0.01 to 1000; Lazarev's fit is meant for 1-30 keV)")(
            "maxwellian", po::bool_switch(&maxwellian),
            "a Maxwellian spectrum with characteristic energy E (number flux ~ E exp(-E/E0)) instead of electrons "
            "all at E")("scene", po::value<std::string>(&sceneFile), "glory: the scene file whose glory table to print");
        cli.addPositional("table", &tableName);
        if (!cli.parse(argc, argv)) {
            out << cli.help();
            return;
        }
        Table table = Table::Deposition;
        if (tableName.empty())
            throw cli.usageError("missing the table name (allowed: " + cli::wordsOf(kTables) + ")");
        if (!cli::findChoice(kTables, tableName, table))
            throw cli.usageError("unknown table '" + echoedInput(tableName) + "' (allowed: " + cli::wordsOf(kTables) + ")");
        if (table == Table::Glory) {
            if (sceneFile.empty() || cli.given("energy-kev") || maxwellian)
                throw cli.usageError("glory takes --scene FILE and nothing else");
            printGloryTable(sceneFile, out);
            return;
        }
        if (!cli.given("energy-kev") || cli.given("scene"))
            throw cli.usageError("deposition takes --energy-kev E [--maxwellian]");
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
