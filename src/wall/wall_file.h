#pragma once
// Reads a wall file (config/walls/*.ini; the format is in docs/walls.md).
#include "wall/wall.h"

#include <string>

namespace aurorawall::wall {

// Throws aurorawall::InputError ("file:line: problem") for a missing file, bad syntax, an unknown,
// missing, duplicate or out-of-range key, overlapping screens, or ranks that do not form 0..N-1.
Wall loadWall(const std::string& path);

} // namespace aurorawall::wall
