#pragma once
// Where a command may write: inside the output folder (--out), so that a client cannot write wherever
// the master's user may. `screenshot`, `record start` and `movie start` share this rule.
#include <filesystem>
#include <string>

namespace aurorawall::app::control {

// outputDir/path for `what path` (e.g. "screenshot x.png"): path must be relative and hold no '..'
// component, and its folder must exist. Throws CommandError "WHAT PATH: REASON".
std::filesystem::path insideOutputFolder(const std::string& what, const std::string& path,
                                         const std::string& outputDir);

} // namespace aurorawall::app::control
