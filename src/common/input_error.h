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

// "file:line: message" (line 0 means the whole file).
inline InputError inputError(const std::string& file, int line, const std::string& message)
{
    return InputError(line > 0 ? file + ":" + std::to_string(line) + ": " + message
                               : file + ": " + message);
}

} // namespace aurorawall
