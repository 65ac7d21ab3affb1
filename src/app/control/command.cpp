#include "app/control/command.h"

#include "common/decimal_number.h"
#include "common/input_error.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <sstream>
#include <vector>

namespace aurorawall::app::control {

namespace {

struct Grammar {
    const char* word;
    CommandKind kind;
    int numbers;    // numeric arguments
    bool path;      // one path argument (the rest of the line is not split)
    const char* usage;
};

const Grammar kGrammar[] = {
    {"status", CommandKind::Status, 0, false, "status"},
    {"pause", CommandKind::Pause, 0, false, "pause"},
    {"play", CommandKind::Play, 0, false, "play"},
    {"speed", CommandKind::Speed, 1, false, "speed FACTOR"},
    {"step", CommandKind::Step, 0, false, "step"},
    {"time", CommandKind::Time, 1, false, "time SECONDS"},
    {"goto", CommandKind::Goto, 3, false, "goto LAT_DEG LON_DEG ALT_KM"},
    {"look", CommandKind::Look, 2, false, "look HEADING_DEG PITCH_DEG"},
    {"preset", CommandKind::Preset, 0, true, "preset NAME"},
    {"orbit", CommandKind::Orbit, 3, false, "orbit LAT_DEG LON_DEG ALT_KM | orbit off"},
    {"screenshot", CommandKind::Screenshot, 0, true, "screenshot PATH.png"},
    {"record", CommandKind::RecordStart, 0, true, "record start PATH.toml | record stop"},
    {"movie", CommandKind::MovieStart, 0, true, "movie start [exr] DIR | movie stop"},
    {"quit", CommandKind::Quit, 0, false, "quit"},
};

std::string knownWords()
{
    std::string words;
    for (const Grammar& g : kGrammar)
        words += (words.empty() ? "" : " ") + std::string(g.word);
    return words;
}

double number(const std::string& word, const Grammar& g)
{
    const std::optional<double> value = common::finiteDecimal(word);
    if (!value)
        throw CommandError(std::string(g.word) + ": '" + common::echoedInput(word) + "' is not a finite number (usage: " + g.usage + ")");
    return *value;
}

void checkRange(bool ok, const std::string& message)
{
    if (!ok)
        throw CommandError(message);
}

bool endsWith(const std::string& text, const std::string& end)
{
    return text.size() > end.size() && text.compare(text.size() - end.size(), end.size(), end) == 0;
}

// A path argument: the rest of the line after `word` (the line's first word, or a word after
// it), blanks at its ends removed (a name may hold spaces).
std::string restOfLine(const std::string& line, const std::string& word, const Grammar& g)
{
    const size_t first = line.find_first_not_of(" \t");
    const size_t after = line.find(word, word == g.word ? first : first + std::string(g.word).size());
    const size_t start = line.find_first_not_of(" \t\r", after + word.size());
    if (start == std::string::npos)
        throw CommandError(std::string(g.word) + ": missing the " + (g.kind == CommandKind::Preset ? "name" : "path") +
                           " (usage: " + g.usage + ")");
    const size_t last = line.find_last_not_of(" \t\r");
    return line.substr(start, last + 1 - start);
}

// `record start PATH.toml`, `record stop`, `movie start [exr] DIR`, `movie stop`. A movie's folder named
// exr needs the word twice (`movie start exr exr`): alone after start, it is the folder.
Command startOrStop(const std::string& line, const std::vector<std::string>& words, const Grammar& g)
{
    const bool record = g.kind == CommandKind::RecordStart;
    Command c;
    if (words.size() >= 2 && words[1] == "stop") {
        if (words.size() > 2)
            throw CommandError(std::string(g.word) + " stop: no argument expected (usage: " + g.usage + ")");
        c.kind = record ? CommandKind::RecordStop : CommandKind::MovieStop;
        return c;
    }
    if (words.size() < 2 || words[1] != "start")
        throw CommandError(std::string(g.word) + ": start or stop expected (usage: " + g.usage + ")");
    c.kind = g.kind;
    c.exr = !record && words.size() >= 4 && words[2] == "exr";
    c.path = restOfLine(line, c.exr ? "exr" : "start", g);
    if (record)
        checkRange(endsWith(c.path, ".toml"), "record start " + c.path + ": the file name must end in .toml");
    return c;
}

} // namespace

Command parseCommand(const std::string& line)
{
    // Commands are printable text: a control byte (a NUL, an escape) is refused by its value and
    // column, and never echoed back.
    for (size_t i = 0; i < line.size(); ++i) {
        const unsigned char c = static_cast<unsigned char>(line[i]);
        if ((c < 0x20 && c != '\t' && c != '\r') || c == 0x7f) {
            char text[96];
            std::snprintf(text, sizeof text, "the line has the control byte 0x%02x at column %zu", c, i + 1);
            throw CommandError(text);
        }
    }
    std::istringstream in(line);
    std::vector<std::string> words;
    for (std::string w; in >> w;)
        words.push_back(w);
    if (words.empty())
        throw CommandError("empty line (commands: " + knownWords() + ")");
    const Grammar* grammar = nullptr;
    for (const Grammar& g : kGrammar)
        if (words[0] == g.word)
            grammar = &g;
    if (!grammar)
        throw CommandError("unknown command '" + common::echoedInput(words[0]) + "' (commands: " + knownWords() + ")");
    const Grammar& g = *grammar;
    Command c;
    c.kind = g.kind;
    const size_t arguments = words.size() - 1;
    if (c.kind == CommandKind::Orbit && arguments == 1 && words[1] == "off") {
        c.kind = CommandKind::OrbitOff;
        return c;
    }
    if (c.kind == CommandKind::RecordStart || c.kind == CommandKind::MovieStart)
        return startOrStop(line, words, g);
    if (g.path) {
        c.path = restOfLine(line, g.word, g);
        if (c.kind == CommandKind::Preset)
            return c;
        checkRange(endsWith(c.path, ".png"), std::string(g.word) + " " + c.path + ": the file name must end in .png");
        return c;
    }
    if (arguments != static_cast<size_t>(g.numbers))
        throw CommandError(std::string(g.word) + ": " + std::to_string(g.numbers) + " argument" +
                           (g.numbers == 1 ? "" : "s") + " expected, got " + std::to_string(arguments) +
                           " (usage: " + g.usage + ")");
    for (int i = 0; i < g.numbers; ++i)
        c.values[i] = number(words[1 + i], g);
    const double* v = c.values;
    switch (c.kind) {
    case CommandKind::Speed:
        checkRange(v[0] >= kMinSpeed && v[0] <= kMaxSpeed, "speed: the factor must be in [0.1, 1000]");
        break;
    case CommandKind::Time:
        checkRange(std::abs(v[0]) <= kMaxTimeS, "time: |seconds| must be <= 1e15");
        break;
    case CommandKind::Goto:
        checkRange(std::abs(v[0]) <= 90, "goto: the latitude must be in [-90, 90] degrees");
        checkRange(std::abs(v[1]) <= 360, "goto: the longitude must be in [-360, 360] degrees");
        checkRange(v[2] >= kMinAltitudeKm && v[2] <= kMaxAltitudeKm, "goto: the altitude must be in [0.001, 1e6] km");
        break;
    case CommandKind::Orbit:
        checkRange(std::abs(v[0]) <= 90, "orbit: the latitude must be in [-90, 90] degrees");
        checkRange(std::abs(v[1]) <= 360, "orbit: the longitude must be in [-360, 360] degrees");
        checkRange(v[2] >= kMinPivotAltitudeKm && v[2] <= kMaxAltitudeKm, "orbit: the altitude must be in [0, 1e6] km");
        break;
    case CommandKind::Look:
        checkRange(std::abs(v[0]) <= 360, "look: the heading must be in [-360, 360] degrees");
        checkRange(std::abs(v[1]) <= 90, "look: the pitch must be in [-90, 90] degrees");
        break;
    default:
        break;
    }
    return c;
}

} // namespace aurorawall::app::control
