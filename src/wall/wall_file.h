#pragma once
// Reads a wall file (config/walls/*.toml; the format is in docs/walls.md).
#include "wall/wall.h"

#include <string>

namespace aurorawall::wall {

// Throws aurorawall::InputError ("file:line: key: problem") for a missing file, a TOML syntax
// error, an unknown, missing, duplicate or out-of-range key, overlapping screens, ranks that do not
// form 0..N-1, or a wall file in the old INI form (".ini", or INI-only lines such as
// "mode = windowed").
Wall loadWall(const std::string& path);

} // namespace aurorawall::wall
