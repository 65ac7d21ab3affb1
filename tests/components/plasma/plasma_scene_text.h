#pragma once
// The head of a scene file for the plasma's settings tests: the planet, an aurora of one curtain and the
// plasma, before the plasma's own table.
#include <string>

namespace aurorawall::test {

inline std::string plasmaSceneHead()
{
    return "[scene]\nname = \"t\"\ncomponents = [\"planet\", \"aurora\", \"plasma\"]\n"
           "[camera]\nlatitude_deg = 0.0\nlongitude_deg = 0.0\naltitude_km = 1.0\n"
           "heading_deg = 0.0\nelevation_deg = 10.0\n"
           "[[aurora.curtain]]\npoints_lat_lon_deg = [[0.0, 0.0], [0.0, 1.0]]\n";
}

} // namespace aurorawall::test
