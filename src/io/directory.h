#pragma once
// Checks on output folders given by the user.
#include <string>

namespace aurorawall::io {

// Creates `dir` with its parents if missing, then checks that files can be created in it by
// creating and deleting a probe file. Throws aurorawall::InputError with one line naming the
// option, the path and the OS reason, e.g.
//   "--out /proc/x: cannot create directory (No such file or directory)".
void ensureWritableDirectory(const std::string& dir, const std::string& optionName);

// Checks that the file `path` can be written: its folder exists (it is not created) and files can
// be created in it, and `path` is nothing yet or a regular file (not a folder, a device or a pipe). Throws aurorawall::InputError with one line naming
// the option, the path and the reason, e.g. "--stats /nonexist/s.csv: folder /nonexist does not exist".
void ensureWritableFile(const std::string& path, const std::string& optionName);

} // namespace aurorawall::io
