// The aurora's sweep of `aurorawall accuracy --scene` and its table `tables deposition`.
#include "components/aurora/tools/aurora_accuracy.h"
#include "components/aurora/tools/deposition_table.h"
#include "components/tools.h"

namespace aurorawall::components::aurora::tools {

const Tools& registered()
{
    static const Tools tools{{}, {}, {}, runSceneAccuracy,
                             "the aurora's;\n"
                             "fluid_cells, box_steps_per_cell where the scene has fluid_detail or the plasma box",
                             {depositionTable()}};
    return tools;
}

} // namespace aurorawall::components::aurora::tools
