// The glory's command (mie), its table of `aurorawall accuracy` and its table of a scene.
#include "components/glory/tools/glory_accuracy.h"
#include "components/glory/tools/glory_table_csv.h"
#include "components/glory/tools/mie_command.h"
#include "components/tools.h"

namespace aurorawall::components::glory::tools {

const Tools& registered()
{
    static const Tools tools{
        {{"mie", "exact Mie scattering by one sphere (mie --n 1.33 --k 0 --x 100 [--angles-deg 0,180])", runMieCommand}},
        {{"glory", "the glory's quality knobs on this scene file",
          "error against cost of the glory's knobs on a scene that lists it: the table's resolution (glory\n"
          "angles, wavelengths, size-parameter step) against the error of its colour per angle and the time to build\n"
          "it, compared with the finer table of the CPU reference; then the colour per pixel (the colour table, or 1\n"
          "to 32 wavelengths per pixel spaced evenly or importance sampled) against the error of the image and the\n"
          "time per frame, compared with the GPU render from the reference's table.\n",
          runGloryAccuracy}},
        {{"glory",
          "CSV gamma_deg, p_<L>nm at each table wavelength, r, g, b: the scene's glory table (the drops'\n"
          "size-averaged phase function, smeared by the light's disc) at each angle from the antisolar point,\n"
          "and its colour per unit of the deck's geometric factor (docs/GLORY.md).\n",
          printGloryTable}}};
    return tools;
}

} // namespace aurorawall::components::glory::tools
