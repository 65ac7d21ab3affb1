#include "components/glory/tools/glory_table_csv.h"

#include "physics/constants.h"
#include "components/glory/glory.h"
#include "components/registry.h"

#include <cstdio>
#include <ostream>
#include <stdexcept>
#include <vector>

namespace aurorawall::components::glory::tools {


void printGloryTable(const std::string& sceneFile, std::ostream& out)
{
    const scene::Scene scene = components::loadScene(sceneFile);
    if (!scene.has("glory"))
        throw std::runtime_error(sceneFile + ": the scene does not list glory");
    const auto& settings = scene.settings<Settings>();
    const optics::PhaseTable table = gloryTables(settings).phase;
    const std::vector<glm::dvec3> rgb = optics::gloryLinearSrgb(optics::gloryXyz(table, settings.light));
    out << "gamma_deg";
    for (double nm : table.wavelengthsNm) {
        char name[32];
        std::snprintf(name, sizeof name, ",p_%gnm", nm);
        out << name;
    }
    out << ",r,g,b\n";
    for (int a = 0; a < table.angles.size(); ++a) {
        char cell[40];
        std::snprintf(cell, sizeof cell, "%.6f", table.angles.angle(a) / physics::kDegree);
        out << cell;
        for (size_t w = 0; w < table.wavelengthsNm.size(); ++w) {
            std::snprintf(cell, sizeof cell, ",%.8g", table.at(int(w), a));
            out << cell;
        }
        for (int channel = 0; channel < 3; ++channel) {
            std::snprintf(cell, sizeof cell, ",%.8g", rgb[size_t(a)][channel]);
            out << cell;
        }
        out << '\n';
    }
}

} // namespace aurorawall::components::glory::tools
