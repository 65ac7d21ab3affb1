// The plasma's commands.
#include "components/plasma/tools/plasma_command.h"
#include "components/tools.h"

namespace aurorawall::components::plasma::tools {

const Tools& registered()
{
    static const Tools tools{
        {{"plasma",
          "the particle-in-cell plasma: verify [--case NAME] against theory, soak --scene F (long\n"
          "            runs of a scene's plasma), accuracy (error against run time)",
          runPlasmaCommand}},
        {},
        {}};
    return tools;
}

} // namespace aurorawall::components::plasma::tools
