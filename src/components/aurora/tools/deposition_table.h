#pragma once
// The aurora's `aurorawall tables deposition --energy-kev E [--maxwellian]` (components/tools.h):
// the Lazarev energy deposition rate over altitude (docs/aurora-physics.md).
#include "components/tools.h"

namespace aurorawall::components::aurora::tools {

const OptionTable& depositionTable();

} // namespace aurorawall::components::aurora::tools
