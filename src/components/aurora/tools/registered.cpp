// The aurora's sweep of `aurorawall accuracy --scene`.
#include "components/aurora/tools/aurora_accuracy.h"
#include "components/tools.h"

namespace aurorawall::components::aurora::tools {

const Tools& registered()
{
    static const Tools tools{{}, {}, {}, runSceneAccuracy,
                             "the aurora's;\n"
                             "fluid_cells, box_steps_per_cell where the scene has fluid_detail or the plasma box"};
    return tools;
}

} // namespace aurorawall::components::aurora::tools
