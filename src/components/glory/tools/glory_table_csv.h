#pragma once
// `aurorawall tables glory --scene FILE`: the glory's table of a scene as CSV.
#include <iosfwd>
#include <string>

namespace aurorawall::components::glory::tools {

// The scene's smeared phase table and its colour: CSV gamma_deg, P at each table wavelength, then the
// colour's linear sRGB per unit of the deck's geometric factor (cd/m^2). Throws when the scene file
// cannot be read, is malformed or does not list glory.
void printGloryTable(const std::string& sceneFile, std::ostream& out);

} // namespace aurorawall::components::glory::tools
