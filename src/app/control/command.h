#pragma once
// One line of the wall's control protocol (docs/driving.md), parsed: a word and its arguments.
// No sockets and no clock here, so that the grammar is tested on its own.
#include <stdexcept>
#include <string>

namespace aurorawall::app::control {

enum class CommandKind {
    Status, Pause, Play, Speed, Step, Time, Goto, Look, Preset, Orbit, OrbitOff, Screenshot,
    RecordStart, RecordStop, MovieStart, MovieStop, Quit
};

// The accepted bounds of the arguments.
constexpr double kMinSpeed = 0.1;    // animation seconds per frame step, relative to --dt (or to real time)
constexpr double kMaxSpeed = 1000.0;
constexpr double kMaxTimeS = 1e15;   // |animation time|, as --start-time
constexpr double kMinAltitudeKm = 0.001; // goto: above the ground
constexpr double kMaxAltitudeKm = 1e6;
constexpr double kMinPivotAltitudeKm = 0.0; // orbit: the point may lie on the ground

struct Command {
    CommandKind kind = CommandKind::Status;
    // speed: the factor; time: seconds; goto: latitude (deg), longitude (deg), altitude (km);
    // look: heading (deg clockwise from north), pitch (deg above the horizontal);
    // orbit: the point's latitude (deg), longitude (deg), altitude (km).
    double values[3] = {0.0, 0.0, 0.0};
    // screenshot: the PNG to write; preset: the preset's name or scene file; record start: the TOML to
    // write; movie start: the folder to write into
    std::string path;
    bool exr = false; // movie start exr: each frame also as OpenEXR (linear, half float), as --movie-exr
};

// A line that is not a command; what() is the reason, one line, without the "error " of the answer.
class CommandError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// Parses one line (without its newline; a trailing '\r' and surrounding blanks are ignored).
// Words are separated by blanks; numbers are finite decimals. Throws CommandError for an empty or
// unknown word, a wrong number of arguments, a malformed number or one outside its bounds.
Command parseCommand(const std::string& line);

} // namespace aurorawall::app::control
