#pragma once
// Atomic file output: a reader (or a crash) never sees a partly written file under its final name.
#include <functional>
#include <string>

namespace aurorawall::io {

// The temporary name used while writing `path`: ".<name>.tmp-<pid>" in the same folder, so that
// the final rename stays within one file system (rename(2) is atomic only there).
std::string temporaryPathFor(const std::string& path);

// Calls writeTemporary(temporaryPathFor(path)), which must write the complete file there and throw
// on any failure; then flushes the temporary to disk (fsync) and renames it to `path`, replacing
// any older file. On any failure the temporary is removed, an older file at `path` is left as it
// was, and the exception propagates (std::runtime_error "path: reason" for failures of its own).
void writeFileAtomically(const std::string& path,
                         const std::function<void(const std::string& temporaryPath)>& writeTemporary);

} // namespace aurorawall::io
