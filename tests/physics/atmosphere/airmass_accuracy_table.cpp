// Prints the airmass accuracy table of docs/airmass.md: every method against the exact reference over
// the sweep's rays, with CPU ns per evaluation (a benchmark, not a test).
#include "physics/atmosphere/airmass_accuracy.h"

#include <iostream>

int main()
{
    using namespace aurorawall::physics::atmosphere;
    std::vector<AirmassRay> rays = airmassAccuracyRays();
    std::cout << formatAirmassAccuracyTable(measureAirmassAccuracy(rays, true));
    return 0;
}
