#pragma once
// An error in what the user gave us: a config file, an option, a path.
// what() is one line that names the file and line (or the option) and the problem,
// e.g. "config/walls/x.toml:7: grid.bezel_horizontal_mm: must be a finite number in [0, 1e+06] (got -3)".
#include <stdexcept>
#include <string>

namespace aurorawall {

class InputError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// A mistake on the command line itself: an unknown, missing or repeated option, a malformed value, a
// value out of range or not among the allowed words, options that contradict each other, or (render)
// a number of MPI ranks other than the wall file's. Commands exit with status 2 for it and 1 for any
// other error, a malformed file included (app/cli/exit_status.h).
class UsageError : public InputError {
public:
    using InputError::InputError;
};

// "file:line: message" (line 0 means the whole file).
inline InputError inputError(const std::string& file, int line, const std::string& message)
{
    return InputError(line > 0 ? file + ":" + std::to_string(line) + ": " + message
                               : file + ": " + message);
}

} // namespace aurorawall
