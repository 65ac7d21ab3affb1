// The aurora's sweep of `aurorawall accuracy --scene`.
#include "components/aurora/tools/aurora_accuracy.h"
#include "components/tools.h"

namespace aurorawall::components::aurora::tools {

const Tools& registered()
{
    static const Tools tools{{}, {}, {}, runSceneAccuracy};
    return tools;
}

} // namespace aurorawall::components::aurora::tools
