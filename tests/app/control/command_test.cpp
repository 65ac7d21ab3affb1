// The control protocol's grammar: every command with its arguments, and the lines it refuses.
#include "app/control/command.h"

#include <gtest/gtest.h>

using namespace aurorawall::app::control;

TEST(Command, WordsWithoutArguments)
{
    EXPECT_EQ(parseCommand("status").kind, CommandKind::Status);
    EXPECT_EQ(parseCommand("pause").kind, CommandKind::Pause);
    EXPECT_EQ(parseCommand("play").kind, CommandKind::Play);
    EXPECT_EQ(parseCommand("step").kind, CommandKind::Step);
    EXPECT_EQ(parseCommand("quit").kind, CommandKind::Quit);
    // Blanks around the words and a carriage return (telnet, Windows clients) are ignored.
    EXPECT_EQ(parseCommand("  status \t\r").kind, CommandKind::Status);
}

TEST(Command, NumbersAreParsedExactly)
{
    const Command speed = parseCommand("speed 2.5");
    EXPECT_EQ(speed.kind, CommandKind::Speed);
    EXPECT_EQ(speed.values[0], 2.5);
    EXPECT_EQ(parseCommand("time -1e3").values[0], -1000.0);
    EXPECT_EQ(parseCommand("time +.5").values[0], 0.5);
    EXPECT_EQ(parseCommand("time 7.").values[0], 7.0);
    EXPECT_EQ(parseCommand("time 0.1").values[0], 0.1); // strtod: the nearest double, as the C++ literal
    const Command go = parseCommand("goto 65.5 -25 200");
    EXPECT_EQ(go.kind, CommandKind::Goto);
    EXPECT_EQ(go.values[0], 65.5);
    EXPECT_EQ(go.values[1], -25.0);
    EXPECT_EQ(go.values[2], 200.0);
    const Command look = parseCommand("look 299 10.4");
    EXPECT_EQ(look.kind, CommandKind::Look);
    EXPECT_EQ(look.values[0], 299.0);
    EXPECT_EQ(look.values[1], 10.4);
}

TEST(Command, BoundsAreInclusive)
{
    EXPECT_EQ(parseCommand("speed 0.1").values[0], 0.1);
    EXPECT_EQ(parseCommand("speed 1000").values[0], 1000.0);
    EXPECT_NO_THROW(parseCommand("goto -90 360 0.001"));
    EXPECT_NO_THROW(parseCommand("look -360 90"));
    EXPECT_NO_THROW(parseCommand("time 1e15"));
}

TEST(Command, PresetAndOrbit)
{
    const Command preset = parseCommand("preset  ground-65n \r");
    EXPECT_EQ(preset.kind, CommandKind::Preset);
    EXPECT_EQ(preset.path, "ground-65n");
    EXPECT_EQ(parseCommand("preset /tmp/my view.toml").path, "/tmp/my view.toml");
    const Command orbit = parseCommand("orbit 65 -20.5 0");
    EXPECT_EQ(orbit.kind, CommandKind::Orbit);
    EXPECT_EQ(orbit.values[0], 65.0);
    EXPECT_EQ(orbit.values[1], -20.5);
    EXPECT_EQ(orbit.values[2], 0.0);
    EXPECT_EQ(parseCommand("orbit off").kind, CommandKind::OrbitOff);
}

TEST(Command, ScreenshotTakesTheRestOfTheLineAsItsPath)
{
    const Command shot = parseCommand("screenshot  /tmp/my wall.png \r");
    EXPECT_EQ(shot.kind, CommandKind::Screenshot);
    EXPECT_EQ(shot.path, "/tmp/my wall.png");
    EXPECT_EQ(parseCommand("screenshot a.png").path, "a.png");
}

TEST(Command, RecordAndMovieStartTakeTheRestOfTheLine)
{
    const Command record = parseCommand(" record  start  paths/my flight.toml \r");
    EXPECT_EQ(record.kind, CommandKind::RecordStart);
    EXPECT_EQ(record.path, "paths/my flight.toml");
    EXPECT_EQ(parseCommand("record stop").kind, CommandKind::RecordStop);
    const Command movie = parseCommand("movie start clips/take 1");
    EXPECT_EQ(movie.kind, CommandKind::MovieStart);
    EXPECT_EQ(movie.path, "clips/take 1");
    EXPECT_FALSE(movie.exr);
    const Command exr = parseCommand("movie start  exr  clips/take 2");
    EXPECT_TRUE(exr.exr);
    EXPECT_EQ(exr.path, "clips/take 2");
    const Command folderExr = parseCommand("movie start exr"); // alone, the word is the folder
    EXPECT_FALSE(folderExr.exr);
    EXPECT_EQ(folderExr.path, "exr");
    EXPECT_TRUE(parseCommand("movie start exr exr").exr);
    EXPECT_EQ(parseCommand("movie start exr exr").path, "exr");
    EXPECT_EQ(parseCommand("movie\tstop ").kind, CommandKind::MovieStop);
    EXPECT_EQ(parseCommand("record start start.toml").path, "start.toml"); // a name may be the subcommand's word
}

// Each refused line with a piece of its reason.
// Control bytes are refused by value and column (a NUL no longer cuts the answer short), and a long
// unknown word is echoed cut.
TEST(Command, ControlBytesAndRawBytesAreNeverEchoed)
{
    const auto refusal = [](const std::string& line) {
        try {
            parseCommand(line);
        } catch (const CommandError& e) {
            return std::string(e.what());
        }
        return std::string("accepted");
    };
    EXPECT_EQ(refusal(std::string("sta\0tus", 7)), "the line has the control byte 0x00 at column 4");
    EXPECT_EQ(refusal("status\x1b[2J"), "the line has the control byte 0x1b at column 7");
    EXPECT_EQ(refusal("time\x7f"), "the line has the control byte 0x7f at column 5");
    const std::string unknown = refusal(std::string(1000, 'x'));
    EXPECT_EQ(unknown.rfind("unknown command '" + std::string(60, 'x') + "… (1000 bytes)' ", 0), 0u) << unknown;
    EXPECT_NO_THROW(parseCommand("status\r"));
    EXPECT_NO_THROW(parseCommand("goto\t65 25 200"));
}

TEST(Command, RefusedLinesSayWhy)
{
    const std::pair<const char*, const char*> cases[] = {
        {"", "empty line"},
        {"   ", "empty line"},
        {"bogus", "unknown command 'bogus'"},
        {"STATUS", "unknown command"},     // words are lower case
        {"status now", "0 arguments expected, got 1"},
        {"speed", "1 argument expected, got 0"},
        {"speed fast", "'fast' is not a finite number"},
        {"speed 2x", "'2x' is not a finite number"},
        {"speed nan", "not a finite number"},
        {"speed inf", "not a finite number"},
        {"time 0x10", "'0x10' is not a finite number"}, // decimals only, as documented
        {"speed 1e", "not a finite number"},
        {"speed .", "not a finite number"},
        {"speed 0.09", "[0.1, 1000]"},
        {"speed 1000.5", "[0.1, 1000]"},
        {"speed -1", "[0.1, 1000]"},
        {"time 2e15", "<= 1e15"},
        {"goto 65 25", "3 arguments expected, got 2"},
        {"goto 91 0 100", "latitude"},
        {"goto 0 361 100", "longitude"},
        {"goto 0 0 0", "altitude"},
        {"goto 0 0 2e6", "altitude"},
        {"look 0 91", "pitch"},
        {"look 400 0", "heading"},
        {"screenshot", "missing the path"},
        {"preset", "preset: missing the name"},
        {"orbit", "3 arguments expected, got 0"},
        {"orbit on", "3 arguments expected, got 1"},
        {"orbit 91 0 0", "orbit: the latitude"},
        {"orbit 0 400 0", "orbit: the longitude"},
        {"orbit 0 0 -1", "orbit: the altitude must be in [0, 1e6] km"},
        {"bogus", "preset"}, // the list of commands
        {"screenshot wall.jpg", "must end in .png"},
        {"screenshot .png", "must end in .png"},
        {"record", "record: start or stop expected (usage: record start PATH.toml | record stop)"},
        {"record go x.toml", "record: start or stop expected"},
        {"record start", "record: missing the path"},
        {"record start x.png", "record start x.png: the file name must end in .toml"},
        {"record start .toml", "must end in .toml"},
        {"record stop now", "record stop: no argument expected"},
        {"movie", "movie: start or stop expected (usage: movie start [exr] DIR | movie stop)"},
        {"movie start  ", "movie: missing the path"},
        {"movie stop x", "movie stop: no argument expected"},
    };
    for (const auto& [line, reason] : cases) {
        try {
            parseCommand(line);
            ADD_FAILURE() << "'" << line << "' was accepted";
        } catch (const CommandError& e) {
            EXPECT_NE(std::string(e.what()).find(reason), std::string::npos)
                << "'" << line << "': " << e.what() << " (expected: " << reason << ")";
            EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << "one line";
        }
    }
}
