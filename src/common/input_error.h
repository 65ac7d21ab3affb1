#pragma once
// An error in what the user gave us: a config file, an option, a path.
// what() is one line that names the file and line (or the option) and the problem,
// e.g. "config/walls/x.toml:7: grid.bezel_horizontal_mm: must be a finite number in [0, 1e+06] (got -3)".
#include <cstddef>
#include <stdexcept>
#include <string>

namespace aurorawall::common {

class InputError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// A mistake on the command line itself: an unknown, missing or repeated option, a malformed value, a
// value out of range or not among the allowed words, options that contradict each other, or (render)
// a number of MPI ranks other than the wall file's. Commands exit with status 2 for it and 1 for any
// other error, a malformed file included (cli/exit_status.h).
class UsageError : public InputError {
public:
    using InputError::InputError;
};

// Text the user gave (an option's value, a word, a field of an input file) as an error message echoes
// it: control characters escaped (\n, \t, \xNN), so that the message stays one line, and text longer
// than kEchoedInputBytes cut there (at a UTF-8 character's start) with an ellipsis and its length:
// "aaaa… (100000000 bytes)". Every error message that echoes input goes through it. File paths that
// locate an error ("file:line: ...") are not echoed input and are kept whole.
inline constexpr std::size_t kEchoedInputBytes = 60;
std::string echoedInput(const std::string& text);

// "file:line: message" (line 0 means the whole file).
inline InputError inputError(const std::string& file, int line, const std::string& message)
{
    return InputError(line > 0 ? file + ":" + std::to_string(line) + ": " + message
                               : file + ": " + message);
}

} // namespace aurorawall::common
