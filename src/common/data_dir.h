#pragma once
#include <string>

namespace aurorawall::common {

// The folder holding shaders/ and config/: $AURORAWALL_DATA_DIR if set; else the installed
// share/aurorawall beside the running executable (../share/aurorawall from bin/); else the source tree
// the program was built from. Never empty.
std::string dataDirectory();

} // namespace aurorawall::common
