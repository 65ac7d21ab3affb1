// The aurora's sweep of `aurorawall accuracy --scene` and its table `tables deposition`.
#include "components/aurora/tools/aurora_accuracy.h"
#include "components/aurora/tools/deposition_table.h"
#include "components/tools.h"

namespace aurorawall::components::aurora::tools {

const Tools& registered()
{
    static const Tools tools{{}, {}, {}, runSceneAccuracy,
                             "the aurora's and those of the other components\n"
                             "the scene lists: fluid_cells, box_steps_per_cell",
                             {depositionTable()}};
    return tools;
}

} // namespace aurorawall::components::aurora::tools
